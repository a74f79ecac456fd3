#!/usr/bin/env bash
# The manifest's one reader outside the programs (tools/jelly_manifest.py, which CMake and the tools
# use): it reads any TOML layout (a list over several lines, keys in any order), writes the keys
# CMake includes, and a bad manifest stops it with the file, the key (or line) and what was
# expected. No build; seconds.
#   test_manifest_reader.sh PYTHON SOURCE_DIR WORK_DIR
set -uo pipefail
py="${1:?python}"; src="${2:?source dir}"; work="${3:?work dir}"
reader="$src/tools/jelly_manifest.py"
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }
rm -rf "$work"; mkdir -p "$work/x"

cat >"$work/x/assignment.toml" <<'TOML'
title = "A test"
files = [
  "a.cpp",   # the first
  "b.cpp",
]
namespace = "x"
id = "x"
[[task]]
id = "X.T1"
TOML
"$py" "$reader" cmake "$work/x/assignment.toml" "$work/x.cmake" 2>"$work/err.txt"
check "a list over several lines is read" 'grep -qxF "set(JELLY_MANIFEST_FILES [==[a.cpp]==] [==[b.cpp]==])" "$work/x.cmake" || { cat "$work/x.cmake" "$work/err.txt"; false; }'
check "an absent optional key is empty" 'grep -qxF "set(JELLY_MANIFEST_DEFAULT_SCENE [==[]==])" "$work/x.cmake"'
check "the manifest hash is recorded" '[ "$(sed -n "s/^set(JELLY_MANIFEST_SHA256 \(.*\))$/\1/p" "$work/x.cmake")" = "$(tr -d "\r" <"$work/x/assignment.toml" | sha256sum | cut -d" " -f1)" ]'
check "get prints a list one item a line" '[ "$("$py" "$reader" get "$work/x/assignment.toml" files | tr "\n" " ")" = "a.cpp b.cpp " ]'

check "an absent draft is OFF" 'grep -qxF "set(JELLY_MANIFEST_DRAFT OFF)" "$work/x.cmake"'
printf 'draft = true\n' | cat - "$work/x/assignment.toml" >"$work/draft.toml"
"$py" "$reader" cmake "$work/draft.toml" "$work/draft.cmake"
check "draft = true is ON" 'grep -qxF "set(JELLY_MANIFEST_DRAFT ON)" "$work/draft.cmake"'
check "get prints a boolean as true or false" '[ "$("$py" "$reader" get "$work/draft.toml" draft)" = true ]'

bad() {  # bad WHAT TEXT EXPECTED
  printf '%s\n' "$2" >"$work/x/assignment.toml"
  "$py" "$reader" cmake "$work/x/assignment.toml" "$work/bad.cmake" >"$work/out.txt" 2>&1
  local rc=$? want="$3"
  check "$1: status 1, names the file and $want" '[ $rc -eq 1 ] && grep -qF -- "$work/x/assignment.toml: $want" "$work/out.txt" || { cat "$work/out.txt"; false; }'
}
bad "no namespace" 'id = "x"
files = ["a.cpp"]' 'namespace: expected a line `namespace = "..."`'
bad "files not a list" 'id = "x"
namespace = "x"
files = "a.cpp"' 'files: expected a list of strings'
bad "not TOML" 'id = "x' 'not valid TOML: '
bad "a file name CMake cannot take" 'id = "x"
namespace = "x"
files = ["a;b.cpp"]' "files: 'a;b.cpp' holds a character CMake cannot take"
bad "a body claim that is not kind or kind:variant" 'id = "x"
namespace = "x"
files = ["a.cpp"]
bodies = ["rope", "disc:"]' 'bodies: expected a body kind'"'"'s name (a scene'"'"'s [body] type: every scene of the kind) or kind:variant (only its scenes of that variant, docs/new-assignment.md), names of letters, digits, '"'"'_'"'"' and '"'"'-'"'"', not "disc:"'
bad "a scene claimed twice (a kind and one of its variants)" 'id = "x"
namespace = "x"
files = ["a.cpp"]
bodies = ["rope:plain", "rope"]' 'bodies: expected each scene claimed once, and "rope:plain" already claims the scenes "rope" does'

bad "draft not a boolean" 'id = "x"
namespace = "x"
files = ["a.cpp"]
draft = "yes"' "draft: expected true or false (\`draft = true\`), not 'yes'"

# `claims`: the bodies, one claim a line, a variant after its kind.
printf 'id = "x"\nnamespace = "x"\nfiles = ["a.cpp"]\nbodies = ["rope:plain", "disc", "rope:braided"]\n' >"$work/x/assignment.toml"
check "claims prints each kind and its variant" '[ "$("$py" "$reader" claims "$work/x/assignment.toml" | tr "\n" "|")" = "rope plain|disc|rope braided|" ]'

# The tree's own manifests: their keys as CMake gets them.
for m in "$src"/assignments/*/assignment.toml; do
  id="$(basename "$(dirname "$m")")"
  "$py" "$reader" cmake "$m" "$work/$id.cmake"
  check "assignments/$id: its id is its folder's name" 'grep -qxF "set(JELLY_MANIFEST_ID [==[$id]==])" "$work/$id.cmake"'
done

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "manifest reader: OK"
