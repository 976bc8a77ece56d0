#!/bin/sh
# Prints the script NAME of a markdown page: the ```sh block that holds a
# comment line "# NAME: ..." (the name the page gives it). Exit 1 if none.
# usage: page_script.sh PAGE NAME
page=$1 name=$2
awk -v name="$name" '
  /^```sh$/ { inside = 1; block = ""; found = 0; next }
  /^```$/ && inside { inside = 0; if (found) { printf "%s", block; done = 1; exit } next }
  inside { block = block $0 "\n"; if (index($0, "# " name ":") == 1) found = 1 }
  END { exit done ? 0 : 1 }
' "$page"
