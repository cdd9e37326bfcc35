#!/usr/bin/env bash
# One case of the mpi label (tests/mpi/CMakeLists.txt): mpi_test.sh PATHSPACE MPIRUN CASE.
# Images are compared byte for byte (EXR and the variance EXR): a distributed render must equal the
# single-process render of the same seed and passes, whatever the ranks and threads.
set -euo pipefail
bin=$1 mpirun=$2 case=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/pathspace-mpi-$case.XXXXXX")
trap 'rm -rf "$work"' EXIT
# Root in containers and CI; more ranks than cores on small machines.
launch() { local n=$1; shift; "$mpirun" --allow-run-as-root --oversubscribe -n "$n" "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

# identical N -- render options: 1 process x 2 threads against N processes x 1 thread.
identical() {
  local n=$1; shift
  "$bin" render "$@" -q -j 2 -o "$work/one.exr" --variance-out "$work/one-var.exr"
  launch "$n" "$bin" render "$@" -q -j 1 -o "$work/many.exr" --variance-out "$work/many-var.exr" --stats "$work/many.json"
  cmp "$work/one.exr" "$work/many.exr" || fail "image differs from the single-process render: $*"
  cmp "$work/one-var.exr" "$work/many-var.exr" || fail "variance differs from the single-process render: $*"
  # Debug images (AOVs), where the options ask for them.
  for aov in "$work"/one.aov-*; do
    [ -e "$aov" ] || continue
    cmp "$aov" "$work/many.${aov#"$work"/one.}" || fail "$(basename "$aov") differs: $*"
  done
  grep -q '"ranks"' "$work/many.json" || fail "--stats has no per-rank table"
}

# A failure must end every rank within 30 s with the message and a non-zero status, leaving no process.
fails_with() {
  local pattern=$1; shift
  local status=0
  timeout 30 "$@" > "$work/out.txt" 2>&1 || status=$?
  [ "$status" -ne 0 ] || fail "exit status 0"
  [ "$status" -ne 124 ] || fail "did not end within 30 s"
  grep -q "$pattern" "$work/out.txt" || { cat "$work/out.txt" >&2; fail "no message matching '$pattern'"; }
  sleep 1
  ! pgrep -f "$work" > /dev/null || fail "processes left behind"
}

small=(cornell-box -r 48x40 --seed 7)
case $case in
  identical_pt) identical 2 "${small[@]}" -i pt -s 5 ;;
  identical_pt_hashed) identical 2 "${small[@]}" -i pt --filter hashed -s 5 ;;
  identical_pt_consistent) identical 2 "${small[@]}" -i pt --filter consistent -s 5 ;;
  identical_lt) identical 2 "${small[@]}" -i lt -s 5 ;;
  identical_bpt) identical 2 "${small[@]}" -i bpt --bpt-strategy-images 3 -s 5 ;;
  identical_sppm) identical 2 "${small[@]}" -i sppm -s 5 ;;
  identical_pclt) identical 2 "${small[@]}" -i pclt -s 5 ;;
  identical_pt_3_ranks) identical 3 "${small[@]}" -i pt -s 7 ;;
  time_agreement)
    launch 2 "$bin" render "${small[@]}" -q -j 1 -t 1.5 -o "$work/t.exr" --stats "$work/t.json"
    # Every rank rendered the same number of passes: the job stopped at a round boundary.
    python3 - "$work/t.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
passes = [r["passes"] for r in j["ranks"]]
assert len(passes) == 2 and passes[0] == passes[1] and sum(passes) == j["spp"], (passes, j["spp"])
PY
    ;;
  scene_unreadable_on_one_rank)
    # Rank 1 reads a damaged copy of the scene file (as root a mode cannot make a file unreadable).
    scene=$(cd "$(dirname "$0")/../../scenes/glass-caustic" && pwd)/scene.pbrt
    mkdir "$work/rank1" && echo 'Shape "nonsense' > "$work/rank1/scene.pbrt"
    fails_with "rank 1" "$mpirun" --allow-run-as-root --oversubscribe -n 2 bash -c 'f=$1; [ "$OMPI_COMM_WORLD_RANK" = 1 ] && f=$2/rank1/scene.pbrt; exec "$0" render "$f" -q -s 2 -r 16x16 -o "$2/x.exr"' \
      "$bin" "$scene" "$work" ;;
  options_mismatch)
    fails_with "other options" "$mpirun" --allow-run-as-root --oversubscribe -n 2 bash -c 's=1; [ "$OMPI_COMM_WORLD_RANK" = 1 ] && s=2; exec "$0" render cornell-box --seed $s -q -s 2 -r 16x16 -o "$1/x.exr"' \
      "$bin" "$work" ;;
  *) fail "unknown case $case" ;;
esac
echo "ok $case"
