#!/usr/bin/env bash
# The benchmarks' whole pipeline (bench/run-all) at its smallest, so the scripts cannot break
# unnoticed: every CSV and machine.json is written, and every error figure is a number; every
# chart too, when /usr/bin/python3 has matplotlib (without it the scripts skip the charts).
# Timings are measured there, never asserted here.
# Usage: bench_smoke.sh SOURCE_DIR BUILD_DIR WORKDIR [RADIOSITY_CHECKED]
set -uo pipefail
source=$1 build=$2 work=$3 checked=${4:-}
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# The experiments run BUILD_DIR/radiosity: given the wrapper that checks each solve's report.json
# against docs/reference/report.schema.json (tests/tools/radiosity_checked.py), they run it from a
# build folder of links to BUILD_DIR's own entries but that one.
if [ -n "$checked" ]; then
  mkdir -p "$work/build"
  for entry in "$build"/*; do ln -s "$entry" "$work/build/"; done
  ln -sfn "$checked" "$work/build/radiosity"
  build="$work/build"
fi

/usr/bin/python3 "$source/bench/run-all" --tiny --build "$build" --output "$work/out" --work "$work/scratch" \
  >"$work/log" 2>&1 || fail "bench/run-all --tiny: $(tail -20 "$work/log")"

if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  for name in accuracy-facing-squares scaling-cores scaling-size stability-a-near-field stability-b-small-receiver \
              stability-c-reflectance stability-d-leaks stability-e-tiny-emitter stability-f-slivers exchange furnace \
              render-modes render-modes-specular specular-box; do
    for ext in png svg; do
      [ -s "$work/out/$name.$ext" ] || fail "no $name.$ext"
    done
  done
  charts="every chart"
else
  echo "note: /usr/bin/python3 has no matplotlib, so no charts are expected"
  charts="no charts (no matplotlib)"
fi
for name in accuracy-facing-squares scaling-cores scaling-cores-runs scaling-size stability-a-near-field \
            stability-b-small-receiver stability-c-reflectance stability-d-leaks stability-e-tiny-emitter \
            stability-f-slivers stability-summary exchange furnace render-modes render-modes-specular specular-box; do
  [ "$(wc -l < "$work/out/$name.csv")" -ge 2 ] || fail "$name.csv has no rows"
done
[ -s "$work/out/machine.json" ] || fail "no machine.json"
if [ -x "$build/bench/bench_embree_compare" ]; then
  [ "$(wc -l < "$work/out/embree-compare.csv")" -ge 2 ] || fail "embree-compare.csv has no rows"
  if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    [ -s "$work/out/embree-compare.png" ] || fail "no embree-compare.png"
  fi
fi
if [ "$(nproc)" -gt 1 ]; then  # the solve by stage compares 1 thread with nproc
  for name in scaling-stages scaling-stages-runs; do
    [ "$(wc -l < "$work/out/$name.csv")" -ge 4 ] || fail "$name.csv has not a row per counter layout"
  done
  if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    [ -s "$work/out/scaling-stages.png" ] || fail "no scaling-stages.png"
  fi
fi
if [ -x "$build/bench/bench_allreduce" ] && command -v mpirun >/dev/null; then
  for name in scaling-mpi scaling-mpi-runs scaling-mpi-allreduce scaling-mpi-model; do
    [ "$(wc -l < "$work/out/$name.csv")" -ge 2 ] || fail "$name.csv has no rows"
  done
  /usr/bin/python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if rows and all(r["bitwise_one_rank"] == "True" for r in rows) else 1)' "$work/out/scaling-mpi.csv" ||
    fail "bench/scaling --mpi: ranks that did not give one rank's radiosities"
fi
/usr/bin/python3 - "$work/out" <<'PY' || fail "bad figures in the CSV files"
import csv, math, sys
out = sys.argv[1]
def rows(name):
    with open("%s/%s.csv" % (out, name), newline="") as f:
        return list(csv.DictReader(f))
for r in rows("accuracy-facing-squares"):
    for k in ("seconds", "surface_error", "image_error"):
        assert math.isfinite(float(r[k])) and float(r[k]) >= 0, (k, r)
for r in rows("scaling-cores"):
    assert float(r["efficiency"] or r["median_seconds"]) > 0, r
for r in rows("stability-summary"):
    assert math.isfinite(float(r["worst"])), r
PY
echo "ok: bench/run-all --tiny wrote every CSV and machine.json, and $charts"
