# expect STATUS TEXT command...: the command exits with STATUS and prints TEXT (stdout or stderr);
# otherwise the case is printed and counted in $failures. Sourced by the command-line suites.
expect() {
  local status=$1 text=$2
  shift 2
  local output
  output=$("$@" 2>&1)
  local got=$?
  if [[ $got -ne $status || "$output" != *"$text"* ]]; then
    echo "FAIL: $* -> exit $got (expected $status), output:"
    echo "$output" | head -5
    echo "  (expected to contain: $text)"
    failures=$((failures + 1))
  fi
}
