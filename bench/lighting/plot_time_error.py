#!/usr/bin/env python3
"""Draws bench/lighting/time_error.svg from the tables of bench/lighting/results.md: the quadrature
paths of area lights (Gauss-Legendre order q: rect, sphere) and the environment light's specular sums
(one curve per lobe, one point per down-sampled level), as error against time per vertex, log-log.

Standard library only (matplotlib is not installed here): the SVG is written by hand.
Usage: bench/lighting/plot_time_error.py [results.md] [out.svg]
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def table_after(lines, heading_prefix):
    """Rows (lists of cells) of the first markdown table after the heading that starts with the prefix."""
    start = next(i for i, line in enumerate(lines) if line.startswith(heading_prefix))
    rows, seen_table = [], False
    for line in lines[start + 1:]:
        if line.startswith("|"):
            seen_table = True
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not set("".join(cells)) <= set("-: "):
                rows.append(cells)
        elif seen_table:
            break
    return rows[1:]  # without the header


def series(results):
    lines = open(results).read().splitlines()
    out = {}
    for light, q, ns, max_err, _median in table_after(lines, "### Quadrature: time against error"):
        out.setdefault(f"{light} quadrature (q = 2..32)", []).append((float(ns), float(max_err), f"q={q}"))
    for path, ns, max_err, _median in table_after(lines, "### Environment: time against error"):
        m = re.match(r"S (phong|blinn) (\d+), (\d+)x(\d+)", path)
        if m and max_err not in ("-", ""):
            key = f"environment S, {m.group(1)} {m.group(2)} (levels)"
            out.setdefault(key, []).append((float(ns), float(max_err), f"{m.group(3)}x{m.group(4)}"))
    return out


def main():
    results = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results.md")
    out_path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "time_error.svg")
    data = series(results)
    xs = [x for s in data.values() for x, _, _ in s]
    ys = [max(y, 1e-16) for s in data.values() for _, y, _ in s]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    W, H, L, R, T, B = 820, 520, 80, 300, 40, 60
    pw, ph = W - L - R, H - T - B

    def px(x):
        return L + (math.log10(x) - x0) / (x1 - x0) * pw

    def py(y):
        return T + (y1 - math.log10(max(y, 1e-16))) / (y1 - y0) * ph

    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{L}" y="22" font-size="14">bake-lighting quadrature paths: error against time per vertex '
           f'(bench/lighting/results.md)</text>']
    for e in range(x0, x1 + 1):
        svg.append(f'<line x1="{px(10**e):.1f}" y1="{T}" x2="{px(10**e):.1f}" y2="{T + ph}" stroke="#ddd"/>')
        svg.append(f'<text x="{px(10**e):.1f}" y="{T + ph + 18}" text-anchor="middle">1e{e}</text>')
    for e in range(y0, y1 + 1):
        svg.append(f'<line x1="{L}" y1="{py(10**e):.1f}" x2="{L + pw}" y2="{py(10**e):.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{L - 6}" y="{py(10**e) + 4:.1f}" text-anchor="end">1e{e}</text>')
    svg.append(f'<rect x="{L}" y="{T}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    svg.append(f'<text x="{L + pw / 2}" y="{H - 18}" text-anchor="middle">ns per vertex (one thread)</text>')
    svg.append(f'<text x="18" y="{T + ph / 2}" transform="rotate(-90 18 {T + ph / 2})" text-anchor="middle">'
               f'max error (relative; environment: of the peak)</text>')
    colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]
    for k, (name, pts) in enumerate(sorted(data.items())):
        c = colours[k % len(colours)]
        pts = sorted(pts)
        path = " ".join(f"{'M' if i == 0 else 'L'}{px(x):.1f},{py(y):.1f}" for i, (x, y, _) in enumerate(pts))
        svg.append(f'<path d="{path}" fill="none" stroke="{c}" stroke-width="1.5"/>')
        for x, y, label in pts:
            svg.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{c}"><title>{name} {label}: '
                       f'{x:g} ns, {y:.2e}</title></circle>')
        ly = T + 10 + 18 * k
        svg.append(f'<line x1="{L + pw + 15}" y1="{ly}" x2="{L + pw + 35}" y2="{ly}" stroke="{c}" stroke-width="2"/>')
        svg.append(f'<text x="{L + pw + 40}" y="{ly + 4}">{name}</text>')
    svg.append("</svg>")
    with open(out_path, "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
