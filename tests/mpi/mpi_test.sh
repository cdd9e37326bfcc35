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

# one.exr and many.exr, their variance images and debug images (AOVs, where asked for) are equal.
same_images() {
  cmp "$work/one.exr" "$work/many.exr" || fail "image differs from the single-process render: $*"
  cmp "$work/one-var.exr" "$work/many-var.exr" || fail "variance differs from the single-process render: $*"
  for aov in "$work"/one.aov-*; do
    [ -e "$aov" ] || continue
    cmp "$aov" "$work/many.${aov#"$work"/one.}" || fail "$(basename "$aov") differs: $*"
  done
}
one=(-q -j 2 -o "$work/one.exr" --variance-out "$work/one-var.exr")
many=(-q -j 1 -o "$work/many.exr" --variance-out "$work/many-var.exr" --stats "$work/many.json")

# identical N -- render options: 1 process x 2 threads against N processes x 1 thread.
identical() {
  local n=$1; shift
  "$bin" render "$@" "${one[@]}"
  launch "$n" "$bin" render "$@" "${many[@]}"
  same_images "$@"
  grep -q '"ranks"' "$work/many.json" || fail "--stats has no per-rank table"
}

# Kills rank 1 of a render with periodic checkpoints once one exists: mpirun must end within 30 s,
# non-zero, leaving no process; resuming the checkpoint with 2 ranks to a fixed total must equal one
# process rendering that total.
kill_and_resume() {
  local opts=(cornell-box -r 96x80 --seed 7 -i pt)
  "$mpirun" --allow-run-as-root --oversubscribe -n 2 "$bin" render "${opts[@]}" -q -j 1 -s 1000000 -o "$work/killed.exr" \
    --checkpoint "$work/ck" --checkpoint-every 0.5 --write-every 0.5 > "$work/out.txt" 2>&1 &
  local job=$! status=0 victim=""
  for _ in $(seq 300); do [ -s "$work/ck" ] && [ -s "$work/killed.exr" ] && break; sleep 0.1; done
  [ -s "$work/ck" ] || fail "no periodic checkpoint within 30 s"
  [ -s "$work/killed.exr" ] || fail "no periodic output within 30 s"
  for pid in $(pgrep -f -- "--checkpoint $work/ck"); do
    tr '\0' '\n' < "/proc/$pid/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=1 && victim=$pid
  done
  [ -n "$victim" ] || fail "rank 1 not found"
  kill -9 "$victim"
  for _ in $(seq 300); do kill -0 "$job" 2>/dev/null || break; sleep 0.1; done
  kill -0 "$job" 2>/dev/null && fail "mpirun still running 30 s after a rank was killed"
  wait "$job" || status=$?
  [ "$status" -ne 0 ] || fail "mpirun exited 0 after a rank was killed"
  sleep 1
  ! pgrep -f "$work" > /dev/null || fail "processes left behind"
  local done_passes total
  done_passes=$("$bin" info "$work/ck" --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["passes"])')
  total=$((done_passes + 5))
  launch 2 "$bin" render "${opts[@]}" --resume "$work/ck" -s "$total" "${many[@]}"
  "$bin" render "${opts[@]}" -s "$total" "${one[@]}"
  same_images "resumed at $done_passes to $total passes"
}

# frames FIRST LAST -- options: each frame of 2 ranks (chunks: rank 0 the first half) against one
# process; `exact` compares every frame, `first_chunk` only rank 0's (the others start from warm-up
# frames: --temporal histories differ) and checks that the other frames exist.
frames() {
  local mode=$1 first=$2 last=$3; shift 3
  "$bin" render "$@" --frames "$first:$last" -q -j 2 -o "$work/one-%02d.exr"
  launch 2 "$bin" render "$@" --frames "$first:$last" -q -j 1 -o "$work/many-%02d.exr" --stats "$work/frames.json"
  local count=$((last - first + 1))
  for ((f = first; f <= last; ++f)); do
    local name
    name=$(printf %02d "$f")
    [ -s "$work/many-$name.exr" ] || fail "frame $f not written"
    if [ "$mode" = exact ] || [ $((f - first)) -lt $((count / 2)) ]; then
      cmp "$work/one-$name.exr" "$work/many-$name.exr" || fail "frame $f differs: $*"
    fi
  done
  python3 - "$work/frames.json" "$count" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert len(j["frames"]) == int(sys.argv[2]), len(j["frames"])
PY
}

# The consistent filter's switch-off (sec. 2.2): a small radius that shrinks fast stops filtering
# within the first passes; the stats must say so, and the image equal the single-process one.
consistent_switch_off() {
  local n=$1; shift
  identical "$n" "$@"
  python3 - "$work/many.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
after = j["statistics"]["consistent.switched_off_after"]
assert 0 < after < j["spp"], (after, j["spp"])
print("switched off after", after, "of", j["spp"], "passes")
PY
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
  consistent_switch_off) consistent_switch_off 2 "${small[@]}" -i pt --filter consistent --psf-radius-pixels 0.2 --psf-alpha 0.9 -s 9 ;;
  consistent_switch_off_3_ranks) consistent_switch_off 3 "${small[@]}" -i pt --filter consistent --psf-radius-pixels 0.15 --psf-alpha 0.9 -s 9 ;;
  bpt_resume)
    # Every rank restores the strategy images; they must count once.
    opts=("${small[@]}" -i bpt --bpt-strategy-images 3)
    "$bin" render "${opts[@]}" -q -j 2 -s 3 --checkpoint "$work/ck" -o "$work/first.exr"
    launch 2 "$bin" render "${opts[@]}" --resume "$work/ck" -s 7 "${many[@]}"
    "$bin" render "${opts[@]}" -s 7 "${one[@]}"
    ls "$work"/one.aov-* > /dev/null || fail "no strategy images"
    same_images "${opts[@]}" resumed ;;
  kill_and_resume) kill_and_resume ;;
  # Periodic writes gather the film and BPT's strategy images onto rank 0 mid-run (several times in
  # 41 passes at 0.01 s); the final images must not change.
  periodic_gathers_bpt) identical 3 "${small[@]}" -i bpt --bpt-strategy-images 3 -s 41 --write-every 0.01 ;;
  frames_pt) frames exact 3 7 cornell-moving-sphere -r 40x30 --seed 7 -i pt -s 2 ;;
  frames_consistent) frames exact 0 4 cornell-moving-sphere -r 40x30 --seed 7 -i pt --filter consistent -s 2 ;;
  frames_hashed_temporal) frames first_chunk 0 19 cornell-moving-light -r 40x30 --seed 7 -i pt --filter hashed --temporal hybrid ;;
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
  run_options_mismatch)
    # -s (and -t, --frames) decide how much each rank renders: a rank started with another count is refused.
    fails_with "rank 1 was started with other run options" "$mpirun" --allow-run-as-root --oversubscribe -n 2 bash -c 's=2; [ "$OMPI_COMM_WORLD_RANK" = 1 ] && s=3; exec "$0" render cornell-box -q -s $s -r 16x16 -o "$1/x.exr"' \
      "$bin" "$work" ;;
  *) fail "unknown case $case" ;;
esac
echo "ok $case"
