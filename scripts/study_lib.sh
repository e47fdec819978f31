# Shared by the study scripts (sourced): calc, and run_case, which writes <name>.prm with the
# study's case_file function and runs it on $ranks ranks of $build/periarlequin into
# <name>.log (a run that stops early is reported by the study's table, not here).

# Arithmetic in awk, printed with all the digits a parameter file needs.
calc() { awk "BEGIN { printf \"%.15g\\n\", $1 }"; }

# run_case <name> <arguments of case_file after the name>
run_case() {
  local name=$1
  shift
  case_file "$name" "$@" > "$name.prm"
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$name.prm" > "$name.log" 2>&1 || true
}
