#!/usr/bin/env bash
# Renders the debugger screenshots listed in screenshots/debugger.txt into screenshots/ with
# tv-debugger --app-screenshot under a virtual X server, and rewrites screenshots/DEBUGGER.md
# from the same list.
#
#   app/debugger/regenerate_screenshots.sh [path/to/tv-debugger]  (EXAMPLE=path/to/the example game)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
debugger="$(realpath -m "${1:-$root/build/release/app/debugger/tv-debugger}")"
list="$root/screenshots/debugger.txt"
page="$root/screenshots/DEBUGGER.md"

if [[ ! -x "$debugger" ]]; then
  echo "regenerate_screenshots.sh: no tv-debugger at '$debugger' (build it, or pass its path)" >&2
  exit 2
fi
command -v xvfb-run >/dev/null || { echo "regenerate_screenshots.sh: needs xvfb-run (apt-get install xvfb xauth)" >&2; exit 2; }
export MESA_SHADER_CACHE_DISABLE=true
# Lines that open sample.tvrec show a recording: the example platformer's first 240 frames,
# recorded afresh into a scratch folder the pictures are rendered from (as tests/app does).
example="${EXAMPLE:-$root/build/release/app/examples/tv-example-platformer}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if grep -v '^#' "$list" | grep -q 'sample\.tvrec'; then
  if [[ ! -x "$example" ]]; then
    echo "$(basename "$0"): no tv-example-platformer at '$example' (build it, or set EXAMPLE)" >&2
    exit 2
  fi
  "$example" --frames 240 --record "$work/sample.tvrec" > /dev/null
fi

{
  echo "# Debugger screenshots"
  echo
  echo "The interactive debugger (\`tv-debugger\`) as a person sees it at 1280x720, rendered from"
  echo "the list in [debugger.txt](debugger.txt) by \`app/debugger/regenerate_screenshots.sh\`. Unlike"
  echo "the [goldens](README.md) nothing compares these pixel for pixel; the test that holds the"
  echo "debugger to tv-render's pictures is \`ctest -R viewer.screenshot\`."
} > "$page"

count=0
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  IFS='|' read -r name args caption <<< "$line"
  name="$(echo "$name" | xargs)"
  args="$(echo "$args" | xargs)"
  caption="$(echo "$caption" | sed 's/^ *//; s/ *$//')"
  # shellcheck disable=SC2086  # the arguments are words by design
  (cd "$work" && xvfb-run -a -s "-screen 0 1280x720x24" "$debugger" $args --no-settings \
    --app-screenshot "$root/screenshots/$name.png" > /dev/null)
  {
    echo
    echo "## $name"
    echo
    echo "![$name]($name.png)"
    echo
    echo "$caption"
    echo
    echo "\`tv-debugger $args\`"
  } >> "$page"
  count=$((count + 1))
done < "$list"
echo "regenerate_screenshots.sh: rendered $count images into screenshots/"
