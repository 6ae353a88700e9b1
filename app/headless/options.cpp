#include "options.hpp"

namespace tv::headless {

const char* const kUsage =
    "usage: tv-render [--scene NAME] [--mover NAME | --compare A,B[,C...]] [--tick N | --ticks "
    "a,b,c]\n"
    "                 [--window WxH] [--out FILE.png] [--body I|none] [--view scene|follow|X,Y,W,H]\n"
    "                 [--render-hz R] [--hide a,b] [--show a,b] [--frames K] [--timing]\n"
    "                 [--PARAM VALUE ...]\n"
    "       tv-render --list\n"
    "\n"
    "Renders the debugger's picture of a scene at a tick into a PNG, without a display (OSMesa).\n"
    "  --scene NAME     a registered scene (default bullets-wall; see --list)\n"
    "  --mover NAME     the mover (default continuous)\n"
    "  --compare A,B,.. the same scene and tick for several movers side by side\n"
    "  --tick N         the tick to show (default 1); --ticks a,b,c writes one image per tick\n"
    "  --window WxH     image size in pixels (default 1280x720)\n"
    "  --out FILE       output PNG; {tick} is replaced by the tick. Default:\n"
    "                   <scene>_<mover>_<tick>.png, or <scene>_<A>-vs-<B>_<tick>.png with "
    "--compare\n"
    "  --body I         the body whose moves are traced and inspected (default 0; none: no trace)\n"
    "  --view V         scene: the scene's camera (default); follow: frame the traced body's\n"
    "                   recent moves; X,Y,W,H: this world rect\n"
    "  --render-hz R    draw rate: the render position is interpolated as a game drawing at R Hz\n"
    "                   would; 0 (default) draws the physics state of the tick\n"
    "  --hide a,b       overlays to turn off; --show a,b to turn on (names as in the panel:\n"
    "                   solids bodies grid occupied visited candidates sweep hull substeps hits\n"
    "                   responses history positions pixel-grid labels, or all)\n"
    "  --frames K       ImGui frames rendered before the capture (default 4, at least 2: panels\n"
    "                   placed below auto-sized ones settle on the third)\n"
    "  --timing         print how long a frame takes (stderr; never in the image)\n"
    "  --PARAM VALUE    any parameter of the scene (--list shows each scene's with its default):\n"
    "                   --speed --size --tile --dt --substep --offset ... (as in tv-run, tv-bench\n"
    "                   and the debugger's panel)\n"
    "  --list           scenes and movers with their one-line descriptions\n"
    "Exit status: 0 done, 1 rendering failed, 2 bad command line.\n";

}  // namespace tv::headless
