#!/usr/bin/env bash
# The classic methods from the command line: every --method and --solver runs, with the options
# it reads, and says so in the report; an option the chosen method or solver does not read is
# refused (exit status 2, the option and its owner named, nothing written); Matrix Market
# output is well formed; --enforce both writes reciprocal, closed factors; the memory guard
# refuses too large a matrix with exit status 2.
# Usage: methods.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
cube="$source/scenes/closed-cube.gltf" cornell="$source/scenes/cornell-box.gltf"

declare -A method_options=([shoot]="--rays-per-patch 2000" [hemicube]="--hemicube-res 32" [gather]="--shadow-rays 4")
declare -A solver_options=([progressive]="" [jacobi]="--bounces 2" [gauss-seidel]="--residual 1e-5" [direct]="")
for method in shoot hemicube gather; do
  for solver in progressive jacobi gauss-seidel direct; do
    own="${method_options[$method]} ${solver_options[$solver]}"
    [ "$method/$solver" = shoot/progressive ] && own="--rays 1e6"  # the device's solver: no matrix
    # shellcheck disable=SC2086
    "$radiosity" solve "$cornell" --method "$method" --solver "$solver" --patch-size 0.15 $own --width 16 --height 16 \
      --quiet --output "$work/$method-$solver" 2>"$work/log" || fail "$method / $solver: $(cat "$work/log")"
    grep -q "\"method\": \"$method\"" "$work/$method-$solver/report.json" || fail "$method / $solver: method not in the report"
    grep -q "\"solver\": \"$solver\"" "$work/$method-$solver/report.json" || fail "$method / $solver: solver not in the report"
  done
done
grep -q '"stopped": "bounces"' "$work/shoot-jacobi/report.json" || fail "jacobi with --bounces did not stop by bounces"
echo "ok: every method with every solver"

refuse() {  # name, the owner the message must name, then the arguments
  local name=$1 owner=$2; shift 2
  "$radiosity" "$@" --output "$work/refused-$name" >/dev/null 2>"$work/log"
  local status=$?
  [ $status -eq 2 ] || fail "$name: exit status $status: $(cat "$work/log")"
  [ "$(wc -l < "$work/log")" -eq 1 ] || fail "$name: more than one line: $(cat "$work/log")"
  grep -q -- "is not used by" "$work/log" && grep -q -- "it is an option of .*$owner" "$work/log" ||
    fail "$name: $(cat "$work/log")"
  [ ! -e "$work/refused-$name" ] || fail "$name left output"
  echo "ok: refused $name: $(cat "$work/log")"
}
refuse hemicube-res-with-shoot "--method hemicube" solve "$cornell" --method shoot --hemicube-res 32
refuse bounces-with-gauss-seidel "--solver jacobi" solve "$cornell" --solver gauss-seidel --bounces 2
refuse rays-with-a-matrix "--method shoot --solver progressive" solve "$cornell" --solver direct --rays 1e6
refuse max-memory-on-the-device "a --method other than shoot" solve "$cornell" --max-memory 1G
refuse tolerance-with-jacobi "--solver progressive" solve "$cornell" --solver jacobi --tolerance 1e-4
refuse shadow-rays-with-hemicube "--method gather" viewfactors "$cornell" --method hemicube --shadow-rays 4
refuse rays-per-patch-at-surface-level "--method shoot at --level patch" viewfactors "$cornell" --rays-per-patch 100
refuse rays-at-patch-level "--level surface" viewfactors "$cornell" --level patch --rays 1000

"$radiosity" viewfactors "$cube" --method hemicube --level patch --format mtx --patch-size 0.5 --hemicube-res 16 \
  --output "$work/cube.mtx" 2>/dev/null || fail "mtx"
head -1 "$work/cube.mtx" | grep -q '^%%MatrixMarket matrix coordinate real general$' || fail "mtx header"
size=$(grep -v '^%' "$work/cube.mtx" | head -1)
entries=$(grep -v '^%' "$work/cube.mtx" | tail -n +2 | wc -l)
[ "$(echo "$size" | awk '{print $3}')" -eq "$entries" ] || fail "mtx: header says $size, $entries entries follow"
echo "ok: Matrix Market ($size)"

"$radiosity" viewfactors "$cube" --method shoot --level surface --enforce both --rays 5000 \
  --output "$work/both.csv" 2>"$work/log" || fail "enforce both: $(cat "$work/log")"
grep -q "largest change" "$work/log" || fail "enforce did not report its largest change"
# Faces have equal areas, so reciprocity means F(a,b) = F(b,a); closure means rows sum to 1.
awk -F, 'NR>1 {f[$1","$2]=$3; s[$1]+=$3} END {
  for (k in f) { split(k, p, ","); d = f[k] - f[p[2]","p[1]]; if (d > 1e-9 || d < -1e-9) { print "asymmetric " k; bad=1 } }
  for (r in s) if (s[r] > 1+1e-9 || s[r] < 1-1e-9) { print "row " r " sums to " s[r]; bad=1 }
  exit bad }' "$work/both.csv" || fail "--enforce both output"
echo "ok: --enforce both is reciprocal and closed"

"$radiosity" solve "$cornell" --solver direct --patch-size 0.05 --max-memory 1M --quiet --output "$work/guard" 2>"$work/log"
status=$?
[ $status -eq 2 ] || fail "direct beyond --max-memory exited $status"
grep -q "MiB" "$work/log" || fail "the guard gave no figure: $(cat "$work/log")"
[ ! -e "$work/guard" ] || fail "output left by a refused solve"
"$radiosity" viewfactors "$cornell" --level patch --patch-size 0.05 --rays-per-patch 100 --max-memory 64K \
  --output "$work/guard.csv" 2>"$work/log"
[ $? -eq 2 ] && grep -q "would need about" "$work/log" || fail "the matrix guard: $(cat "$work/log")"
echo "ok: the memory guard refuses with the figure: $(cat "$work/log")"
