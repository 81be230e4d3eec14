#!/usr/bin/env bash
# One command-line case of the argine program: makes a deck variant from a base deck,
# runs argine on it and checks the exit code and a pattern in its output.
#   cli_case.sh ARGINE BASE_DECK EXPECTED_EXIT PATTERN SED_EXPR [COMMAND...]
# SED_EXPR edits the base deck ("-" for none); COMMAND defaults to "check"; the word DECK in
# COMMAND stands for the edited deck and OUT for a scratch output directory.
set -uo pipefail
argine=$1 base=$2 expected_exit=$3 pattern=$4 edit=$5
shift 5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck="$work/deck.yaml"
if [[ "$edit" == "-" ]]; then cp "$base" "$deck"; else sed -e "$edit" "$base" >"$deck"; fi
command=("$@")
((${#command[@]})) || command=(check DECK)
for i in "${!command[@]}"; do
  command[$i]=${command[$i]//DECK/$deck}
  command[$i]=${command[$i]//OUT/$work/out}
done
output=$("$argine" "${command[@]}" 2>&1)
status=$?
echo "$output"
if [[ $status -ne $expected_exit ]]; then
  echo "FAIL: exit code $status, expected $expected_exit" >&2
  exit 1
fi
if ! grep -qE -- "$pattern" <<<"$output"; then
  echo "FAIL: output does not match /$pattern/" >&2
  exit 1
fi
if [[ $expected_exit -eq 2 && -d "$work/out" ]]; then
  echo "FAIL: an input error still created output in $work/out" >&2
  exit 1
fi
echo "PASS"
