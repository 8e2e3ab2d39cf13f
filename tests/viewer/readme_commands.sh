#!/usr/bin/env bash
# The README's table of script commands is the one the viewer prints from its command list
# (src/viewer/commands.h): a command added, removed or reworded there fails here until the
# README follows (paste `ssrlab-view --help-script` between the viewer-commands markers).
# Usage: readme_commands.sh SSRLAB_VIEW README
set -eu
viewer=$1; readme=$2
generated=$("$viewer" --help-script)
documented=$(sed -n '/<!-- viewer-commands: begin -->/,/<!-- viewer-commands: end -->/p' "$readme" | sed '1d;$d')
if [ "$generated" != "$documented" ]; then
  echo "README.md's viewer commands differ from ssrlab-view --help-script:"
  diff <(echo "$documented") <(echo "$generated") || true
  exit 1
fi
echo "README viewer commands match ($(echo "$generated" | grep -c '^| `') commands)"
