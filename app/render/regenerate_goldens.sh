#!/usr/bin/env bash
# Renders every golden screenshot listed in screenshots/goldens.txt into screenshots/, then
# rewrites screenshots/README.md from the same list, so the pictures, their captions and the
# tests (tests/app) never disagree.
#
#   app/render/regenerate_goldens.sh [path/to/tv-render]    (EXAMPLE=path/to/the example game)
#   cmake --build build/release --target tv-goldens        # the same, through CMake
#
# The goldens are pinned to Debian 12's Mesa (llvmpipe): render them there.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
render="$(realpath -m "${1:-$root/build/release/app/render/tv-render}")"
list="$root/screenshots/goldens.txt"
readme="$root/screenshots/README.md"

if [[ ! -x "$render" ]]; then
  echo "regenerate_goldens.sh: no tv-render at '$render' (build it, or pass its path)" >&2
  exit 2
fi

# Lines that open sample.tvrec show a recording: the example platformer's first 240 frames,
# recorded afresh into a scratch folder the pictures are rendered from (as tests/app does).
# Files the other lines name (--map levels/...) are relative to the repository, as in the tests.
example="${EXAMPLE:-$root/build/release/app/examples/tv-example-platformer}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
ln -s "$root/levels" "$work/levels"
if grep -v '^#' "$list" | grep 'sample\.tvrec' > /dev/null; then  # not -q: under pipefail its early exit fails the pipe
  if [[ ! -x "$example" ]]; then
    echo "$(basename "$0"): no tv-example-platformer at '$example' (build it, or set EXAMPLE)" >&2
    exit 2
  fi
  "$example" --frames 240 --record "$work/sample.tvrec" > /dev/null
fi

# Same environment as the tests: no shader cache on disk, the default llvmpipe driver.
export MESA_SHADER_CACHE_DISABLE=true
unset GALLIUM_DRIVER LIBGL_ALWAYS_SOFTWARE

{
  echo "# Golden screenshots"
  echo
  echo "Rendered by \`tv-render\` (OSMesa, llvmpipe, Debian 12) from the list in"
  echo "[goldens.txt](goldens.txt); \`app/render/regenerate_goldens.sh\` (or the CMake target"
  echo "\`tv-goldens\`) renders them all again and rewrites this page. \`ctest -R golden\` renders"
  echo "each one again, under the default rasterizer and under llvmpipe's 128- and 256-bit vector"
  echo "widths, and compares it with the golden. The comparison tolerates what another Mesa build or"
  echo "CPU changes and nothing a reader would see: no pixel may differ by more than 4 levels in any"
  echo "channel, and at most 2% of the pixels may differ at all (Mesa 22.3.6's deb12u1 and deb12u2"
  echo "builds differ on up to 0.66% of the pixels, by at most 2 levels). A line or a body moved by a"
  echo "pixel, a missing label or a palette colour changed by 5 levels fails"
  echo "(tests/app/golden_tolerance_test.cpp); \`TV_GOLDEN_TOLERANCE=C:F\` overrides the bounds."
  echo
  echo "Colours: grey solids, teal bodies (dark once stopped), blue cells shaded by item count,"
  echo "yellow cells the traced move visited, magenta candidates, white sweep, light-blue hull,"
  echo "violet substeps, red hits (rect at touch, normal, touch point), green response targets,"
  echo "cyan/orange/yellow the physics, render and floored-pixel positions; where a scene has them,"
  echo "brown moving solids, a dashed lime line on a one-way side, and the bodies a moving solid"
  echo "carried (blue), pushed (pink) or squished (crimson) that tick, green corner nudges, and the"
  echo "contact events of bodies that read their contacts: a gold diamond where a contact began, a"
  echo "cream line along an edge that still touches, a hollow orange diamond where one ended."
  echo "The legend in every picture says the same."
} > "$readme"

count=0
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  IFS='|' read -r name args caption <<< "$line"
  name="$(echo "$name" | xargs)"
  args="$(echo "$args" | xargs)"
  caption="$(echo "$caption" | sed 's/^ *//; s/ *$//')"
  # shellcheck disable=SC2086  # the arguments are words by design
  (cd "$work" && "$render" $args --out "$root/screenshots/$name.png" > /dev/null)
  {
    echo
    echo "## $name"
    echo
    echo "![$name]($name.png)"
    echo
    echo "$caption"
    echo
    echo "\`tv-render $args\`"
  } >> "$readme"
  count=$((count + 1))
done < "$list"
# The debugger's own screenshots have their page (app/debugger/regenerate_screenshots.sh).
if [[ -f "$root/screenshots/DEBUGGER.md" ]]; then
  {
    echo
    echo "## The debugger"
    echo
    echo "Screenshots of the interactive debugger, tv-debugger: [DEBUGGER.md](DEBUGGER.md)."
  } >> "$readme"
fi
echo "regenerate_goldens.sh: rendered $count images into screenshots/"
