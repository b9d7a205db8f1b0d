#!/usr/bin/env python3
"""report.py DIR: turns the CSVs that bench/run.sh wrote into DIR/results.md and
DIR/error_vs_time.png (gnuplot). Standard library only.

Inputs (any may be missing): kernels.csv, refinement.csv, read.csv (bench/compare programs),
e2e.csv (hyperfine), memory.csv, machine.txt. Ratios are always taken between rows of one program
run (same process, same mesh): an anchor's median over shadetool's area/double/1-thread median
measured by the same program.
"""
import csv
import math
import os
import shutil
import subprocess
import sys


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return float("nan")


def fmt_ms(x):
    x = num(x)
    if math.isnan(x):
        return "-"
    return f"{x:.3g}" if x < 100 else f"{x:.0f}"


def fmt_deg(x):
    x = num(x)
    if math.isnan(x):
        return "-"
    if x == 0:
        return "0"
    return f"{x:.3g}" if x >= 1e-3 else f"{x:.1e}"


def fmt_ratio(x):
    return "-" if x is None or math.isnan(x) else f"{x:.2f}x"


def is_ours(r):
    return r["method"].startswith("shadetool")


def ref_row(rows, program, mesh, weighting="area"):
    for r in rows:
        if (r["program"] == program and r["mesh"] == mesh and is_ours(r) and r["method"].endswith("vertex_normals")
                and r["weighting"] == weighting and r["precision"] == "double" and r["threads"] == "1"):
            return r
    return None


def main_mesh(rows):
    names = [r["mesh"] for r in rows if r["mesh"] != "sphere_10k_degenerate"]
    return names[0] if names else None


def kernel_table(rows, mesh):
    """Our kernels (program 'ours') then every anchor with its ratio to our area kernel."""
    out = ["| method | weighting | precision | threads | median ms | min ms | CPU ms | vs our area (same run) "
           "| CPU vs our area | mean deg | p99 deg | max deg | NaN/zero |",
           "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    ours_ref = ref_row(rows, "ours", mesh)
    for r in rows:
        if r["mesh"] != mesh:
            continue
        if is_ours(r) and r["program"] != "ours":
            continue  # the anchors' in-process reference rows are used for ratios, not repeated
        ref = ours_ref if r["program"] == "ours" else ref_row(rows, r["program"], mesh)
        ratio = num(r["median_ms"]) / num(ref["median_ms"]) if ref else float("nan")
        cpu_ratio = num(r["median_cpu_ms"]) / num(ref["median_cpu_ms"]) if ref else float("nan")
        out.append(f"| {r['method']} | {r['weighting']} | {r['precision']} | {r['threads']} | {fmt_ms(r['median_ms'])} "
                   f"| {fmt_ms(r['min_ms'])} | {fmt_ms(r['median_cpu_ms'])} | {fmt_ratio(ratio)} | {fmt_ratio(cpu_ratio)} "
                   f"| {fmt_deg(r['mean_deg'])} | {fmt_deg(r['p99_deg'])} "
                   f"| {fmt_deg(r['max_deg'])} | {r['nan_or_zero']} |")
    return out


def degenerate_table(rows):
    mesh = "sphere_10k_degenerate"
    sel = [r for r in rows if r["mesh"] == mesh and r["method"].find("face_normals") < 0
           and not (is_ours(r) and r["program"] != "ours")]
    if not sel:
        return []
    out = ["| method | weighting | precision | threads | NaN or zero normals | vertices without a normal | note |",
           "|---|---|---|---|---:|---:|---|"]
    seen = set()
    for r in sel:
        key = (r["method"], r["weighting"], r["precision"])
        if key in seen:
            continue
        seen.add(key)
        out.append(f"| {r['method']} | {r['weighting']} | {r['precision']} | {r['threads']} | {r['nan_or_zero']} "
                   f"| {r['missing']} | {r['note']} |")
    return out


def find(rows, **kw):
    for r in rows:
        if all(r.get(k) == v for k, v in kw.items()):
            return r
    return None


def targets(rows, read_rows, e2e_rows, mem_rows, mesh):
    """One line per goal of the benchmark issue, from wall-clock medians (the goal) and, beside it,
    from CPU-time medians (less disturbed by other processes on a shared machine)."""
    res = []

    def pair(slow, fast, wall="median_ms", cpu="median_cpu_ms"):
        if not slow or not fast:
            return None, None
        w = num(slow[wall]) / num(fast[wall])
        c = num(slow[cpu]) / num(fast[cpu]) if cpu in slow and cpu in fast else float("nan")
        return w, c

    # "plain": vertex_normals(mesh) as the CLI calls it (allocates its output, plans nothing);
    # "prepared": a VertexNormalsPlan built once per connectivity and the output array reused, which
    # is how the anchors with prebuilt topology and preallocated properties (OpenMesh) are timed.
    def ours(program, weighting, threads="1", precision="double", prepared=False):
        method = "shadetool vertex_normals (prepared)" if prepared else "shadetool vertex_normals"
        return find(rows, program=program, mesh=mesh, method=method, weighting=weighting,
                    precision=precision, threads=threads)

    def add(name, values, goal, higher_is_better=True):
        w, c = values
        if w is None or math.isnan(w):
            res.append(f"| {name} | not measured | - | {'>=' if higher_is_better else '<='} {goal}x | - |")
            return
        ok = w >= goal if higher_is_better else w <= goal
        cs = "-" if c is None or math.isnan(c) else f"{c:.2f}x"
        res.append(f"| {name} | {w:.2f}x | {cs} | {'>=' if higher_is_better else '<='} {goal}x | {'met' if ok else 'MISSED'} |")

    # Like with like: OpenMesh's float traits against our float path, its double traits against our
    # double path (each plain and prepared).
    for prec in ("float", "double"):
        for prep in (False, True):
            add(f"OpenMesh update_normals ({prec} traits) time / our {prec} area time ({'prepared' if prep else 'plain'})",
                pair(find(rows, program="openmesh", mesh=mesh, method="OpenMesh update_normals", precision=prec),
                     ours("openmesh", "area", precision=prec, prepared=prep)), 5)
    for prep in (False, True):
        add(f"Open3D ComputeVertexNormals time / our area time ({'prepared' if prep else 'plain'})",
            pair(find(rows, program="open3d", mesh=mesh, method="Open3D ComputeVertexNormals", threads="1"),
                 ours("open3d", "area", prepared=prep)), 2)
    for w in ("angle", "max"):
        add(f"our {w} time / our area time (double, 1 thread)", pair(ours("ours", w), ours("ours", "area")), 2,
            higher_is_better=False)
    # Threads: prepared calls run in parallel for every weighting; a plain call plans its parallel
    # sum only for angle and max (the plan costs about half the area kernel, so plain area stays
    # serial); plain rows shown for honesty.
    plain_label = {"area": "plain: serial by design", "angle": "plain: planned per call"}
    for w in ("area", "angle"):
        for prep in (True, False):
            w1, w2 = ours("ours", w, "1", prepared=prep), ours("ours", w, "2", prepared=prep)
            add(f"2-thread speed-up, our {w} (double, {'prepared' if prep else plain_label[w]})",
                (num(w1["median_ms"]) / num(w2["median_ms"]), None) if w1 and w2 else (None, None), 1.7)
    if read_rows:
        rm = main_mesh(read_rows)
        ours_obj = find(read_rows, mesh=rm, method="shadetool read_mesh", weighting="obj", threads="1")
        om_obj = find(read_rows, mesh=rm, method="OpenMesh IO::read_mesh", weighting="obj")
        ours_ply = find(read_rows, mesh=rm, method="shadetool read_mesh", weighting="ply", threads="1")
        fr = find(read_rows, mesh=rm, method="fread", weighting="ply")
        add(f"OpenMesh IO::read_mesh OBJ time / our OBJ read time ({rm})", pair(om_obj, ours_obj), 5)
        add(f"our binary PLY read time / fread time ({rm})", pair(ours_ply, fr), 3, higher_is_better=False)
    e2e_ours = next((r for r in e2e_rows if r["command"].startswith("shadetool normals OBJ->PLY (area)")), None)
    e2e_asm = next((r for r in e2e_rows if r["command"] == "assimp export -gsn OBJ->PLY"), None)
    if e2e_ours and e2e_asm:
        cpu = lambda r: num(r["user"]) + num(r["system"])
        add("assimp export -gsn time / shadetool normals time, OBJ -> binary PLY",
            (num(e2e_asm["median"]) / num(e2e_ours["median"]), cpu(e2e_asm) / cpu(e2e_ours)), 5)
    else:
        add("assimp export -gsn time / shadetool normals time, OBJ -> binary PLY", (None, None), 5)
    if mem_rows:
        add(f"peak memory / arrays held ({mem_rows[0]['mesh']})", (num(mem_rows[0]["ratio"]), None), 2, higher_is_better=False)
    else:
        add("peak memory / arrays held", (None, None), 2, higher_is_better=False)
    return [f"| target ({mesh}, one run) | wall-time medians | CPU-time medians | goal | |",
            "|---|---:|---:|---:|---|"] + res


def refinement_tables(rows):
    if not rows:
        return [], []
    # mean error by (surface, kind, weighting, precision) -> {size: (triangles, mean)}
    data = {}
    f32 = []
    rows = [r for r in rows if r["method"] == "shadetool vertex_normals"]
    for r in rows:
        surface, size, kind = r["mesh"].split("_")
        data.setdefault((surface, kind, r["weighting"], r["precision"]), {})[size] = (num(r["triangles"]), num(r["mean_deg"]), num(r["max_deg"]))
        if r["precision"] == "float":
            d = find(rows, mesh=r["mesh"], weighting=r["weighting"], precision="double")
            note = r["note"]
            worst = note.split("max angle to double result ")[1].split(" deg")[0] if "max angle to double result" in note else "nan"
            if d:
                f32.append((r["mesh"], r["weighting"], abs(num(r["mean_deg"]) - num(d["mean_deg"])),
                            abs(num(r["max_deg"]) - num(d["max_deg"])), num(worst)))
    sizes = ["10k", "1M", "4M"]
    out = ["| surface | kind | weighting | mean deg 10k | mean deg 1M | mean deg 4M | order 10k->1M | order 1M->4M |",
           "|---|---|---|---:|---:|---:|---:|---:|"]
    for (surface, kind, w, p), d in sorted(data.items()):
        if p != "double":
            continue
        cells = [fmt_deg(d[s][1]) if s in d else "-" for s in sizes]

        def order(a, b):
            if a not in d or b not in d or d[a][1] <= 0 or d[b][1] <= 0:
                return "-"
            if max(d[a][1], d[b][1]) < 1e-9:
                return "exact"  # rounding only (max weighting on a sphere): no discretisation error to order
            # error ~ h^p with h ~ triangles^(-1/2)
            return f"{-2 * math.log(d[b][1] / d[a][1]) / math.log(d[b][0] / d[a][0]):.2f}"
        out.append(f"| {surface} | {kind} | {w} | {' | '.join(cells)} | {order('10k', '1M')} | {order('1M', '4M')} |")
    worst_mean = max(f32, key=lambda x: x[2]) if f32 else None
    worst_angle = max(f32, key=lambda x: (x[4] if not math.isnan(x[4]) else -1)) if f32 else None
    f32_lines = []
    if f32:
        f32_lines.append(f"- float vs double, over {len(f32)} (mesh, weighting) pairs: largest difference of mean error "
                         f"{worst_mean[2]:.2e} deg ({worst_mean[0]}, {worst_mean[1]}); largest difference of max error "
                         f"{max(x[3] for x in f32):.2e} deg; largest angle between a float and a double vertex normal "
                         f"{worst_angle[4]:.2e} deg ({worst_angle[0]}, {worst_angle[1]}). Goal: within 1e-3 deg: "
                         f"{'met' if max(max(x[2], x[3]) for x in f32) <= 1e-3 else 'MISSED'}.")
    return out, f32_lines


def read_table(rows):
    if not rows:
        return []
    out = ["| reader | format | threads | median ms | min ms | vs fread / vs OpenMesh |", "|---|---|---|---:|---:|---:|"]
    for r in rows:
        ref = None
        if r["method"] != "fread":
            if r["weighting"] == "ply":
                fr = find(rows, mesh=r["mesh"], method="fread")
                ref = f"{num(r['median_ms']) / num(fr['median_ms']):.1f}x fread" if fr else "-"
            om = find(rows, mesh=r["mesh"], method="OpenMesh IO::read_mesh", weighting=r["weighting"])
            if om and r["method"] != om["method"]:
                ref = (ref + ", " if ref else "") + f"{num(om['median_ms']) / num(r['median_ms']):.1f}x faster than OpenMesh"
        out.append(f"| {r['method']} | {r['weighting']} | {r['threads']} | {fmt_ms(r['median_ms'])} | {fmt_ms(r['min_ms'])} | {ref or '-'} |")
    return out


def e2e_table(rows, acc):
    if not rows:
        return []
    acc = {a["command"]: a for a in acc}
    ref = next((r for r in rows if r["command"].startswith("shadetool normals OBJ->PLY (area)")), None)
    out = ["| command | median s | mean s | stddev s | CPU s (user+sys) | vs shadetool OBJ->PLY (area), wall | same, CPU "
           "| output: vertices | mean deg | p99 deg | max deg | NaN/zero |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    cpu = lambda r: num(r["user"]) + num(r["system"])
    for r in rows:
        ratio = num(r["median"]) / num(ref["median"]) if ref else float("nan")
        cratio = cpu(r) / cpu(ref) if ref else float("nan")
        a = acc.get(r["command"])
        tail = (f"{a['vertices']} | {fmt_deg(a['mean_deg'])} | {fmt_deg(a['p99_deg'])} | {fmt_deg(a['max_deg'])} | {a['nan_or_zero']}"
                if a else "- | - | - | - | -")
        out.append(f"| {r['command']} | {num(r['median']):.3f} | {num(r['mean']):.3f} | {num(r['stddev']):.3f} | {cpu(r):.3f} "
                   f"| {fmt_ratio(ratio)} | {fmt_ratio(cratio)} | {tail} |")
    return out


def plot(rows, mesh, outdir):
    """error_vs_time.png: mean angular error against median time, one point (and legend entry) per
    method at 1 thread; shadetool as circles, the anchors as squares."""
    if not shutil.which("gnuplot") or not mesh:
        return None
    pts = []
    for r in rows:
        if r["mesh"] != mesh or r["threads"] != "1" or math.isnan(num(r["mean_deg"])):
            continue
        if is_ours(r) and r["program"] != "ours":
            continue
        label = (r["method"].replace("shadetool vertex_normals", "shadetool").replace("Open3D ComputeVertexNormals", "Open3D")
                 .replace("CGAL PMP::compute_vertex_normals", "CGAL").replace("assimp GenSmoothNormals", "assimp"))
        label = f"{label} {r['weighting']} {'f32' if r['precision'] == 'float' else 'f64'}"
        pts.append((num(r["median_ms"]), max(num(r["mean_deg"]), 1e-14), label, is_ours(r)))
    if not pts:
        return None
    png = os.path.join(outdir, "error_vs_time.png")
    colors = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"]
    plots, data = [], []
    for i, (t, e, label, ours) in enumerate(pts):
        plots.append(f"'-' using 1:2 with points pt {7 if ours else 5} ps 1.8 lc rgb '{colors[i % len(colors)]}' "
                     f"title '{label}'")
        data.append(f"{t} {e}\ne")
    script = f"""
set terminal pngcairo size 1200,650 font ",10" noenhanced
set output "{png}"
set title "Vertex normals on {mesh}: mean angular error to the analytic normal vs median time, 1 thread"
set xlabel "median time per call [ms] (log scale)"
set ylabel "mean angular error [deg] (log scale)"
set logscale xy
set grid
set key outside right top box
set format y "1e%L"
plot {", ".join(plots)}
{chr(10).join(data)}
"""
    try:
        subprocess.run(["gnuplot"], input=script, text=True, check=True, capture_output=True)
    except (subprocess.CalledProcessError, OSError) as e:
        print(f"report.py: gnuplot failed: {getattr(e, 'stderr', e)}", file=sys.stderr)
        return None
    return png


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results")
    kernels = read_csv(os.path.join(d, "kernels.csv"))
    refinement = read_csv(os.path.join(d, "refinement.csv"))
    reads = read_csv(os.path.join(d, "read.csv"))
    e2e = read_csv(os.path.join(d, "e2e.csv"))
    mem = read_csv(os.path.join(d, "memory.csv"))
    machine = open(os.path.join(d, "machine.txt")).read().strip() if os.path.exists(os.path.join(d, "machine.txt")) else ""
    mesh = main_mesh(kernels)
    png = plot(kernels, mesh, d)
    md = ["# shadetool benchmark results", "",
          "Made by `bench/run.sh` (`bench/report.py`); the CSV files beside this one hold every number.", "",
          "```", machine, "```", ""]
    md += ["## Targets", ""] + targets(kernels, reads, e2e, mem, mesh) + [""]
    md += [f"## Vertex normals on {mesh} (kernels; same mesh in one process; IO excluded)", "",
           "Ratios are to shadetool's area-weighted double kernel at 1 thread timed by the same program in the same "
           "run (>1x: slower than ours). Error: angle to the analytic normal over all vertices.", ""]
    md += kernel_table(kernels, mesh) + [""]
    if png:
        md += [f"![mean angular error against time]({os.path.basename(png)})", ""]
    deg = degenerate_table(kernels)
    if deg:
        md += ["## Degenerate input (sphere_10k_degenerate)", "",
               "The 10k irregular sphere plus 100 each of: faces with a repeated index, faces with two coincident "
               "vertices, collinear faces, isolated vertices (900 vertices at risk). Counted over all vertices.", ""]
        md += deg + [""]
    ref, f32 = refinement_tables(refinement)
    if ref:
        md += ["## Error under refinement (shadetool, double)", "",
               "Order p from mean error ~ h^p with h ~ triangles^(-1/2); \"exact\": the error is rounding only.", ""]
        md += ref + [""] + f32 + [""]
    rt = read_table(reads)
    if rt:
        md += [f"## Reading {main_mesh(reads)} (file in page cache)", ""] + rt + [""]
    et = e2e_table(e2e, read_csv(os.path.join(d, "e2e_accuracy.csv")))
    if et:
        e2e_txt = os.path.join(d, "e2e.txt")
        inp = [l for l in open(e2e_txt).read().splitlines() if l.startswith("input:")] if os.path.exists(e2e_txt) else []
        md += ["## End to end (hyperfine)", ""] + inp + [""] + et + [""]
    if mem:
        m = mem[0]
        md += ["## Peak memory", "",
               f"`shadetool normals {m['mesh']} --weight area`: peak RSS {num(m['peak_rss_bytes']) / 2**20:.0f} MiB; "
               f"arrays it must hold (positions 24 V + faces 16 F + 4 + vertex normals 24 V, V = {m['vertices']}, "
               f"F = {m['triangles']}) {num(m['array_bytes']) / 2**20:.0f} MiB: ratio {num(m['ratio']):.2f} "
               f"(file {num(m['file_bytes']) / 2**20:.0f} MiB, wall {m['wall']}).", ""]
    with open(os.path.join(d, "results.md"), "w") as f:
        f.write("\n".join(md))
    print(os.path.join(d, "results.md"))


if __name__ == "__main__":
    main()
