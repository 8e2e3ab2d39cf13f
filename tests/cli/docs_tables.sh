#!/usr/bin/env bash
# The documents' tables are the code's: the README's technique, scene and view tables and
# docs/PARAMETERS.md are what `ssrlab techniques|scenes|views --markdown` print from the
# registry, the parameter tables, the scene list and the view table. A row added, removed or
# reworded in the code fails here until the document follows (paste the command's output
# between the markers, or into docs/PARAMETERS.md).
# Usage: docs_tables.sh SSRLAB SOURCE_DIR
set -eu
ssrlab=$1; src=$2
fail=0
check() {  # name, generated text, documented text
  if [ -z "$2" ]; then  # a failed command and a missing marker would otherwise "match"
    echo "$1: the generated text is empty"
    fail=1
  elif [ "$2" != "$3" ]; then
    echo "$1 differs from the generated text:"
    diff <(echo "$3") <(echo "$2") | head -20 || true
    fail=1
  else
    echo "$1 matches ($(echo "$2" | wc -l) lines)"
  fi
}
section() { sed -n "/<!-- $1: begin -->/,/<!-- $1: end -->/p" "$src/README.md" | sed '1d;$d'; }
check "README techniques" "$("$ssrlab" techniques --markdown)" "$(section techniques)"
check "README scenes" "$("$ssrlab" scenes --markdown)" "$(section scenes)"
check "README views" "$("$ssrlab" views --markdown)" "$(section views)"
check "docs/PARAMETERS.md" "$("$ssrlab" techniques --markdown parameters)" "$(cat "$src/docs/PARAMETERS.md")"
exit $fail
