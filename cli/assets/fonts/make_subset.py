#!/usr/bin/env python3
"""Builds DejaVuSans-subset.ttf, the font of the PNG charts (cli/src/chart/font.rs).

    python3 cli/assets/fonts/make_subset.py [/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf]

Needs fontTools (pip install fonttools); tested with fontTools 4.68 and DejaVu Sans 2.37.

1. Starts from the full DejaVu Sans.
2. Adds one composite glyph per combining sequence the chart labels use (σ̄, γ̃): the base
   glyph with the mark centred over it, mapped to a Private Use Area code point. plotters'
   glyph renderer draws every glyph at the pen position and does no shaping, so a combining
   mark (zero advance, drawn to the left of its origin) would land after its base ("σ¯");
   the PNG writer substitutes each sequence with its code point before drawing. The table
   must match COMPOSED in cli/src/chart/font.rs (a test checks it).
3. Keeps the Unicode blocks the labels draw from (Latin with ū and ḡ, Greek, combining
   marks, punctuation, super- and subscripts, arrows, mathematical operators, geometric
   shapes) and the composites, without hinting or layout tables (the renderer uses neither).
"""

import sys

from fontTools import subset
from fontTools.ttLib import TTFont
from fontTools.ttLib.tables._g_l_y_f import Glyph, GlyphComponent

SOURCE = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
OUT = __file__.rsplit("/", 1)[0] + "/DejaVuSans-subset.ttf" if "/" in __file__ else "DejaVuSans-subset.ttf"

# (base, combining mark, Private Use Area code point): keep in step with font.rs COMPOSED
COMPOSED = [
    ("σ", "\u0304", 0xE000),  # σ̄: mean stress
    ("γ", "\u0303", 0xE001),  # γ̃: reduced surface energy
]

RANGES = [
    (0x20, 0x7E),  # Basic Latin
    (0xA0, 0x17F),  # Latin-1, Latin Extended-A (ū)
    (0x300, 0x36F),  # combining marks
    (0x370, 0x3FF),  # Greek
    (0x1E20, 0x1E21),  # Ḡ ḡ
    (0x2010, 0x205E),  # general punctuation
    (0x2070, 0x209C),  # super- and subscripts
    (0x2190, 0x21FF),  # arrows
    (0x2200, 0x22FF),  # mathematical operators
    (0x25A0, 0x25FF),  # geometric shapes
    (0x27E8, 0x27E9),  # ⟨ ⟩
]


def centre(font, name):
    g = font["glyf"][name]
    g.recalcBounds(font["glyf"])
    return (g.xMin + g.xMax) / 2


def add_composites(font):
    cmap = font.getBestCmap()
    glyf, hmtx = font["glyf"], font["hmtx"]
    for base, mark, code in COMPOSED:
        b, m = cmap[ord(base)], cmap[ord(mark)]
        name = "uni%04X" % code
        g = Glyph()
        g.numberOfContours = -1
        g.components = []
        for glyph, dx in [(b, 0), (m, round(centre(font, b) - centre(font, m)))]:
            c = GlyphComponent()
            c.glyphName, c.x, c.y, c.flags = glyph, dx, 0, 0
            g.components.append(c)
        # the first component's metrics (advance and side bearing) are the composite's
        g.components[0].flags = 0x0200
        glyf[name] = g  # also appends the name to the glyph order
        g.recalcBounds(glyf)
        hmtx[name] = (hmtx[b][0], g.xMin)
        for table in font["cmap"].tables:
            if table.isUnicode():
                table.cmap[code] = name


def main():
    font = TTFont(SOURCE)
    add_composites(font)
    codes = [c for lo, hi in RANGES for c in range(lo, hi + 1)] + [c for _, _, c in COMPOSED]
    options = subset.Options()
    options.hinting = False
    options.name_IDs = ["*"]
    options.notdef_outline = True
    # no shaping or kerning tables: plotters' renderer reads neither
    options.layout_features = []
    options.drop_tables += ["GSUB", "GPOS", "GDEF", "MATH", "FFTM"]
    sub = subset.Subsetter(options)
    sub.populate(unicodes=codes)
    sub.subset(font)
    font.save(OUT)
    print(f"{OUT}: {len(font.getGlyphOrder())} glyphs")


if __name__ == "__main__":
    main()
