#!/usr/bin/env bash
# Checkpoint/restart of a coupled, fracturing run with a PD zone that grows (restart_case.prm),
# interrupted by a signal:
#  1. the reference: the whole run on R ranks, with a checkpoint at the end;
#  2. the same run with a checkpoint every 50 steps, killed (SIGKILL to the whole process
#     group, wherever it is, possibly in the middle of writing a checkpoint) after its second
#     checkpoint; then resumed (Checkpoint/Resume) on R ranks to the end. Its final checkpoint
#     (mesh, FE vectors, particles with their state and broken bonds, record with the whole
#     energy history as binary doubles) and its energy history, last damage map and .pvd records
#     must equal the reference's byte for byte: the state a checkpoint restores is the whole state;
#  3. the killed run resumed on R' ranks (another number), writing checkpoints on a wall-time
#     budget as it goes: the energy history agrees with the reference to 1e-10 of each
#     column's largest magnitude (sums in another order: 1 and 2 ranks agree to 1e-13 in
#     adaptivity/growing_crack_mpi), counts (broken bonds, particles, converted cells)
#     exactly;
#  4. bad checkpoints get a clear error: a truncated record, a cell-data file that does not
#     match its checksum, other parameters, no checkpoint at all.
# Usage: checkpoint_restart.sh <application> <mpiexec> <case.prm> <R> <R'> <work directory>
set -u
app=$1 mpiexec=$2 case_prm=$3 ranks=$4 other_ranks=$5 work=$6
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1

fail() {
  echo "FAILED: $*"
  exit 1
}

# command <ranks>: the launcher for that many ranks.
command_for() {
  if [ "$1" = 1 ]; then
    echo "$app"
  else
    echo "$mpiexec -np $1 $app"
  fi
}

# case_file <file> <output directory> <Checkpoint entries...>
case_file() {
  local file=$1 directory=$2
  shift 2
  {
    cat "$case_prm"
    printf 'subsection Output\n  set Directory = %s\nend\nsubsection Checkpoint\n' "$directory"
    for entry in "$@"; do
      printf '  set %s\n' "$entry"
    done
    printf 'end\n'
  } > "$file"
}

# newest <directory>: the slot the pointer names.
newest() {
  echo "$1/plate_checkpoint_$(cat "$1/plate_checkpoint.last")"
}

# expect_error <what> <log> <regex> <command...>: the command fails with a message matching.
expect_error() {
  local what=$1 log=$2 regex=$3
  shift 3
  if "$@" > "$log" 2>&1; then
    fail "$what: the run was accepted"
  fi
  grep -Eq "$regex" "$log" || { cat "$log"; fail "$what: no message matching '$regex'"; }
  echo "$what: refused with a clear message"
}

# 1. The reference.
case_file reference.prm "$work/reference" "At end = true"
$(command_for "$ranks") reference.prm > reference.log 2>&1 || { cat reference.log; fail "reference run"; }

# A repartition moves the state of the step it follows: its energies are those of the step's
# force pass (not zero, as when the internal force and the energy densities stayed behind).
awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == "strain_energy") k = c; next }
  $1 > 0 && $k == 0 { print "FAILED: no strain energy at step " $1; exit 1 }' \
  reference/plate_energy.csv || fail "energies of the reference"
echo "reference: $(tail -1 reference/plate_energy.csv | cut -d, -f11) broken bonds," \
  "$(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == "repartitions") k = c } END { print $k }' \
  reference/plate_energy.csv) repartitions"

# 2. Killed after its second checkpoint, then resumed.
case_file killed.prm "$work/killed" "Interval = 50"
setsid $(command_for "$ranks") killed.prm > killed.log 2>&1 &
pid=$!
for _ in $(seq 6000); do
  [ "$(grep -c 'checkpoint written' killed.log)" -ge 2 ] && break
  kill -0 "$pid" 2> /dev/null || break
  sleep 0.05
done
kill -KILL -- -"$pid" 2> /dev/null
wait "$pid" 2> /dev/null
# Open MPI may put the ranks in process groups of their own: end every process of the
# session, and wait until none is left, before the checkpoints are copied (a rank that
# outlived mpirun could still be writing the next slot).
pkill -KILL -s "$pid" 2> /dev/null || true
for _ in $(seq 200); do
  pgrep -s "$pid" > /dev/null || break
  sleep 0.05
done
grep -q "Time loop" killed.log && fail "the run ended before it was killed: the case is too short"
[ "$(grep -c 'checkpoint written' killed.log)" -ge 2 ] || { cat killed.log; fail "no checkpoints"; }
echo "killed after $(grep -c 'checkpoint written' killed.log) checkpoints"
for copy in other truncated damaged mismatched; do
  cp -r killed "$copy"
done

case_file resumed.prm "$work/killed" "Interval = 50" "Resume = true" "At end = true"
$(command_for "$ranks") resumed.prm > resumed.log 2>&1 || { cat resumed.log; fail "resumed run"; }
grep "resumed from" resumed.log
for file in mesh mesh.info mesh_fixed.data mesh_variable.data state; do
  a=$(newest reference)/$file b=$(newest killed)/$file
  [ -e "$a" ] || [ -e "$b" ] || continue
  cmp -s "$a" "$b" || fail "final checkpoint file $file differs from the uninterrupted run's"
done
# The .pvd records without the line that dates them.
for file in plate_energy.csv plate_damage_000500.csv plate_fe.pvd plate_pd.pvd; do
  [ -e "reference/$file" ] || fail "the reference wrote no $file"
  cmp -s <(grep -v "generated by the deal.II library" "reference/$file") \
    <(grep -v "generated by the deal.II library" "killed/$file") ||
    fail "$file differs from the uninterrupted run's"
done
echo "killed and resumed on $ranks rank(s): final state, energy history and .pvd records identical to the uninterrupted run"

# 3. Resumed on another number of ranks.
# With checkpoints on a wall-time budget (every 0.2 s), which must not change the run.
case_file other.prm "$work/other" "Resume = true" "Wall time interval = 0.2"
$(command_for "$other_ranks") other.prm > other.log 2>&1 || { cat other.log; fail "run resumed on $other_ranks rank(s)"; }
[ "$(grep -c 'checkpoint written' other.log)" -ge 1 ] || fail "no checkpoint on the wall-time budget"
echo "resumed on $other_ranks rank(s): $(grep -c 'checkpoint written' other.log) checkpoints on the wall-time budget"
awk -F, -v tolerance=1e-10 '
  FNR == 1 { for (c = 1; c <= NF; ++c) column[FILENAME, $c] = c; next }
  FILENAME == ARGV[1] { rows = FNR; for (c = 1; c <= NF; ++c) reference[FNR, c] = $c; next }
  { resumed_rows = FNR; for (c = 1; c <= NF; ++c) resumed[FNR, c] = $c }
  END {
    if (rows != resumed_rows) { print "FAILED: " rows - 1 " against " resumed_rows - 1 " rows"; exit 1 }
    n = split("time kinetic_energy strain_energy external_work total_energy crack_area broken_bond_energy conversion_energy", real, " ")
    for (k = 1; k <= n; ++k) {
      a = column[ARGV[1], real[k]]; b = column[ARGV[2], real[k]]
      if (!a || !b) { print "FAILED: no column " real[k]; exit 1 }
      scale = 0; worst = 0
      for (r = 2; r <= rows; ++r) { v = reference[r, a] < 0 ? -reference[r, a] : reference[r, a]; if (v > scale) scale = v }
      for (r = 2; r <= rows; ++r) { d = reference[r, a] - resumed[r, b]; if (d < 0) d = -d; if (d > worst) worst = d }
      if (scale > 0) worst /= scale
      printf "  %s: %.1e of its largest magnitude\n", real[k], worst
      if (worst > tolerance) { print "FAILED: " real[k] " differs"; exit 1 }
    }
    n = split("broken_bonds pd_particles converted_cells branches", count, " ")
    for (k = 1; k <= n; ++k) {
      a = column[ARGV[1], count[k]]; b = column[ARGV[2], count[k]]
      if (!a || !b) { print "FAILED: no column " count[k]; exit 1 }
      for (r = 2; r <= rows; ++r)
        if (reference[r, a] != resumed[r, b]) { print "FAILED: " count[k] " differs at row " r; exit 1 }
    }
  }' reference/plate_energy.csv other/plate_energy.csv || fail "resumed on $other_ranks rank(s)"
echo "killed on $ranks rank(s), resumed on $other_ranks: energy history within 1e-10, counts identical"

# 4. Bad checkpoints.
slot=$(newest truncated)
head -c 100 "$slot/state" > "$slot/state.cut" && mv "$slot/state.cut" "$slot/state"
case_file truncated.prm "$work/truncated" "Resume = true"
expect_error "truncated record" truncated.log "checkpoint .* is corrupt \\(its record .*state is missing, truncated, or fails its checksum\\)" $(command_for "$ranks") truncated.prm

slot=$(newest damaged)
printf 'X' | dd of="$slot/mesh_variable.data" bs=1 seek=200 conv=notrunc status=none
case_file damaged.prm "$work/damaged" "Resume = true"
expect_error "damaged cell data" damaged.log "is corrupt \\(its file mesh_variable.data is missing or fails its checksum\\)" \
  $(command_for "$ranks") damaged.prm

case_file mismatched.prm "$work/mismatched" "Resume = true"
sed -i "s/set Young's modulus = 72e9/set Young's modulus = 70e9/" mismatched.prm
expect_error "other parameters" mismatched.log \
  "was written with 'Material/Young's modulus = 72e9' where this run has 'Material/Young's modulus = 70e9'" \
  $(command_for "$ranks") mismatched.prm

case_file none.prm "$work/none" "Resume = true"
expect_error "no checkpoint" none.log "Checkpoint/Resume' = true, but .* names no checkpoint" \
  $(command_for "$ranks") none.prm
echo "checkpoint_restart: OK"
