# Sourced by the plot tests: count checks and print the closing line CTest logs read
# ("N passed, N failed"); `die` stops at a check the rest cannot go on without.
passed=0
failed=0
ok() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
summary() { echo "$passed passed, $failed failed"; }
die() { fail "$*"; summary; exit 1; }
not() { ! "$@"; }
expect() {  # expect DESCRIPTION COMMAND...: one check
  local what=$1
  shift
  if "$@"; then ok; else fail "$what"; fi
}
