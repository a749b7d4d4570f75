"""A log-log plot of time and peak memory against parts and instances, as
an SVG written by hand (no plotting library needed): two panels, one line
a series. Reads the series from standard input as JSON,
{"label": [[count, seconds, MiB], ...], ...}, and writes the SVG to the
path given (benches/issue33.sh: SVG=docs/issue33.svg)."""
import json
import math
import sys

series = json.load(sys.stdin)
W, H, M = 900, 380, 60
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#555"]


def panel(x0, title, idx, unit):
    xs = [c for s in series.values() for c, *_ in s]
    vs = [v[idx] for s in series.values() for _, *v in s]
    xl, xh = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    yl = math.floor(math.log10(max(min(vs), 1e-3)))
    yh = math.ceil(math.log10(max(vs)))
    yh = max(yh, yl + 1)
    pw, ph = W / 2 - M - 20, H - 2 * M
    X = lambda c: x0 + M + (math.log10(c) - xl) / (xh - xl) * pw
    Y = lambda v: H - M - (math.log10(max(v, 10**yl)) - yl) / (yh - yl) * ph
    out = [f'<text x="{x0 + M + pw / 2}" y="24" text-anchor="middle" font-weight="bold">{title}</text>',
           f'<rect x="{x0 + M}" y="{M}" width="{pw}" height="{ph}" fill="none" stroke="#888"/>']
    for e in range(xl, xh + 1):
        out.append(f'<text x="{X(10**e):.1f}" y="{H - M + 18}" text-anchor="middle">1e{e}</text>')
    for e in range(yl, yh + 1):
        out.append(f'<text x="{x0 + M - 6}" y="{Y(10**e) + 4:.1f}" text-anchor="end">1e{e}</text>')
        out.append(f'<line x1="{x0 + M}" x2="{x0 + M + pw}" y1="{Y(10**e):.1f}" y2="{Y(10**e):.1f}" stroke="#ddd"/>')
    out.append(f'<text x="{x0 + M + pw / 2}" y="{H - 12}" text-anchor="middle">parts or instances</text>')
    out.append(f'<text x="{x0 + 14}" y="{H / 2}" transform="rotate(-90 {x0 + 14} {H / 2})" '
               f'text-anchor="middle">{unit}</text>')
    for i, (label, s) in enumerate(series.items()):
        pts = " ".join(f"{X(c):.1f},{Y(v[idx]):.1f}" for c, *v in s)
        colour = COLOURS[i % len(COLOURS)]
        out.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="2"/>')
        out += [f'<circle cx="{X(c):.1f}" cy="{Y(v[idx]):.1f}" r="3" fill="{colour}"/>' for c, *v in s]
        out.append(f'<text x="{x0 + M + 8}" y="{M + 16 + 16 * i}" fill="{colour}">{label}</text>')
    return out


body = panel(0, "time", 0, "seconds") + panel(W / 2, "peak memory", 1, "MiB")
with open(sys.argv[1], "w") as f:
    f.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" '
            f'font-size="12"><rect width="{W}" height="{H}" fill="white"/>' + "".join(body) + "</svg>\n")
