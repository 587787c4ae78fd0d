#!/usr/bin/env bash
# The check on report.json can fail: docs/reference/report.schema.json is a valid JSON Schema
# 2020-12; tests/tools/validate_report.py passes the report of a tiny solve and fails copies of
# it with a required key missing, a value of the wrong type, a key the schema does not know, and
# NaN; and tests/tools/radiosity_checked.py, which the other tests run solves through, fails a
# solve whose report does not fit, leaves alone a report the run did not write, and passes on
# exit statuses and signals (a stand-in program writes the reports, so each case is certain).
# Usage: report_schema.sh RADIOSITY_CHECKED SOURCE_DIR WORKDIR (RADIOSITY_CHECKED: the wrapper
# the build generates, tests/CMakeLists.txt)
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
tools="$source/tests/tools"
validate() { python3 "$tools/validate_report.py" "$@"; }

python3 -c '
import json, sys, jsonschema
jsonschema.Draft202012Validator.check_schema(json.load(open(sys.argv[1])))' \
  "$source/docs/reference/report.schema.json" || fail "report.schema.json is not a valid JSON Schema 2020-12"
echo "ok   report.schema.json is a valid JSON Schema 2020-12"

"$radiosity" solve "$source/scenes/cornell-box.gltf" --rays 20000 --patch-size 0.25 --width 8 --height 8 --quiet \
  --output "$work/tiny" 2>"$work/tiny.log" || fail "tiny solve: $(cat "$work/tiny.log")"
report="$work/tiny/report.json"
validate "$report" > "$work/valid.out" || fail "the tiny solve's report does not fit: $(cat "$work/valid.out")"
echo "ok   the tiny solve's report fits"

# mutant NAME EXPECTED PYTHON: a copy of the report changed by PYTHON (on r, the parsed report) must
# fail, the message naming EXPECTED.
mutant() {
  local name=$1 expected=$2 change=$3
  python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
$change
json.dump(r, open(sys.argv[2], 'w'), indent=2)" "$report" "$work/$name.json" || fail "$name: could not make the copy"
  if validate "$work/$name.json" > "$work/$name.out" 2>&1; then fail "$name: passed"; fi
  grep -qF -- "$expected" "$work/$name.out" || fail "$name: no '$expected' in: $(cat "$work/$name.out")"
  echo "ok   $name fails: $(head -1 "$work/$name.out")"
}
mutant missing-key "$work/missing-key.json: \$: 'energy' is a required property" 'del r["energy"]'
mutant missing-nested-key "\$.solve: 'stopped' is a required property" 'del r["solve"]["stopped"]'
mutant wrong-type "\$.mesh.patches: '" 'r["mesh"]["patches"] = str(r["mesh"]["patches"])'
mutant wrong-type-in-array "\$.surfaces[0].radiosity[1]: 'bright'" 'r["surfaces"][0]["radiosity"][1] = "bright"'
mutant unknown-key "\$: Additional properties are not allowed ('seconds_total' was unexpected)" 'r["seconds_total"] = 1.0'
mutant unknown-nested-key "\$.solve: Additional properties are not allowed" 'r["solve"]["shots_per_second"] = 1.0'
mutant unknown-stop-reason "\$.solve.stopped: 'tired'" 'r["solve"]["stopped"] = "tired"'
sed 's/"relative_residual": [^,}]*/"relative_residual": NaN/' "$report" > "$work/nan.json"
if validate "$work/nan.json" > "$work/nan.out" 2>&1; then fail "NaN: passed"; fi
grep -q "NaN is not JSON" "$work/nan.out" || fail "NaN: $(cat "$work/nan.out")"
echo "ok   NaN fails: $(cat "$work/nan.out")"
# A module of that name that cannot be imported hides the installed one.
mkdir -p "$work/hidden" && echo 'raise ImportError("hidden")' > "$work/hidden/jsonschema.py"
PYTHONPATH="$work/hidden" python3 "$tools/validate_report.py" "$report" > "$work/no-module.out" 2>&1 &&
  fail "without jsonschema: passed"
grep -q "jsonschema is missing" "$work/no-module.out" || fail "without jsonschema: $(cat "$work/no-module.out")"
echo "ok   without the jsonschema module the check fails, saying so"

# The wrapper, around a stand-in that writes the report FAKE_REPORT as a solve does (into
# --output, atomically) and ends as FAKE_MODE says.
cat > "$work/fake" <<'PY'
#!/usr/bin/env python3
import os, shutil, signal, sys, time
mode, out = os.environ["FAKE_MODE"], "out"
for i, a in enumerate(sys.argv):
    if a == "--output":
        out = sys.argv[i + 1]
    elif a.startswith("--output="):
        out = a[len("--output="):]
def write():
    os.makedirs(out, exist_ok=True)
    shutil.copy(os.environ["FAKE_REPORT"], os.path.join(out, ".report.tmp"))
    os.replace(os.path.join(out, ".report.tmp"), os.path.join(out, "report.json"))
if mode == "write":
    write()
    sys.exit(int(os.environ.get("FAKE_STATUS", "0")))
if mode == "exit":
    sys.exit(int(os.environ["FAKE_STATUS"]))
if mode == "interrupt":  # as radiosity: a signal stops the work, the outputs are written, status 0
    got = []
    for s in (signal.SIGINT, signal.SIGTERM):
        signal.signal(s, lambda number, frame: got.append(number))
    open(os.environ["FAKE_READY"], "w").close()
    deadline = time.time() + 60
    while not got and time.time() < deadline:
        time.sleep(0.01)
    time.sleep(0.3)  # a second copy of the signal would arrive by now
    write()
    sys.exit(0 if len(got) == 1 else 10 + len(got))
if mode == "die":
    os.kill(os.getpid(), signal.SIGTERM)
PY
chmod +x "$work/fake"
checked() { python3 "$tools/radiosity_checked.py" "$work/fake" solve scene.gltf --quiet "$@"; }
status_of() { "$@"; echo $?; }

[ "$(FAKE_MODE=write FAKE_REPORT="$report" status_of checked --output "$work/w1" 2>&1)" = 0 ] ||
  fail "wrapper: a fitting report did not pass"
FAKE_MODE=write FAKE_REPORT="$work/wrong-type.json" checked --output="$work/w2" >"$work/w2.out" 2>&1
status=$?
[ "$status" -eq 1 ] || fail "wrapper: a report that does not fit gave status $status"
grep -q "mesh.patches" "$work/w2.out" || fail "wrapper: no reason given: $(cat "$work/w2.out")"
echo "ok   wrapper: a solve whose report does not fit fails, saying why ($(grep -c . "$work/w2.out") lines)"
FAKE_MODE=write FAKE_REPORT="$work/wrong-type.json" FAKE_STATUS=3 checked --output "$work/w3" >/dev/null 2>&1
status=$?
[ "$status" -eq 3 ] || fail "wrapper: a failing solve's status 3 became $status"
(cd "$work" && FAKE_MODE=write FAKE_REPORT="$work/unknown-key.json" checked >/dev/null 2>&1)
status=$?
[ "$status" -eq 1 ] || fail "wrapper: the report in the default output folder was not checked ($status)"
[ -s "$work/out/report.json" ] || fail "wrapper: the stand-in wrote no out/report.json"
FAKE_MODE=exit FAKE_STATUS=2 checked --output "$work/w5" >/dev/null 2>&1
status=$?
[ "$status" -eq 2 ] || fail "wrapper: status 2 became $status"
mkdir -p "$work/stale" && cp "$work/unknown-key.json" "$work/stale/report.json"
FAKE_MODE=exit FAKE_STATUS=0 checked --output "$work/stale" || fail "wrapper: a report this run did not write was checked"
FAKE_MODE=exit FAKE_STATUS=0 python3 "$tools/radiosity_checked.py" "$work/fake" viewfactors x --output "$work/stale" ||
  fail "wrapper: a command other than solve was checked"
echo "ok   wrapper: exit statuses passed on; reports this run did not write, and other commands, left alone"

FAKE_MODE=die status_of checked --output "$work/w4" > "$work/w4.status" 2>/dev/null
[ "$(cat "$work/w4.status")" -eq 143 ] || fail "wrapper: a program ended by SIGTERM gave $(cat "$work/w4.status"), not 143"
for sig in INT TERM; do
  rm -f "$work/ready"
  # Not through checked(): $! must be the wrapper's own process.
  FAKE_MODE=interrupt FAKE_REPORT="$report" FAKE_READY="$work/ready" python3 "$tools/radiosity_checked.py" \
    "$work/fake" solve scene.gltf --output "$work/$sig" 2>"$work/$sig.log" &
  pid=$!
  for _ in $(seq 200); do [ -e "$work/ready" ] && break; sleep 0.05; done
  [ -e "$work/ready" ] || fail "SIG$sig: the stand-in did not start"
  kill -"$sig" "$pid"
  wait "$pid"
  status=$?
  [ "$status" -eq 0 ] || fail "SIG$sig to the wrapper (started with &): status $status: $(cat "$work/$sig.log")"
  [ -s "$work/$sig/report.json" ] || fail "SIG$sig: no report"
done
echo "ok   wrapper: SIGINT and SIGTERM reach the program, also from a script's background job; death by a signal passed on"
