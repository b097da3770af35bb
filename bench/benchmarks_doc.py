#!/usr/bin/python3
"""Regenerates the tables of docs/benchmarks.md from the data bench/run_benchmarks.py stored.

Usage: bench/benchmarks_doc.py DATA_DIR DOC.md
DATA_DIR is docs/benchmarks (machine.json, data/<group>/*.json, micro/*.json, plots/*.svg). Only
the text between <!-- BEGIN generated: NAME --> and <!-- END generated: NAME --> is replaced; the
prose around it is kept. Every number comes from DATA_DIR (or, for Mesquite,
bench/driver/mesquite_reference.tsv).
"""
import glob
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
from run_benchmarks import read_mesquite_reference  # noqa: E402

METHOD_ORDER = ["smart-laplace", "laplace", "simultaneous", "sequential", "getme", "warpage"]
METHOD_LABEL = {
    "smart-laplace": "Smart Laplace",
    "laplace": "Laplace",
    "simultaneous": "GETMe simultaneous",
    "sequential": "GETMe sequential",
    "getme": "GETMe",
    "warpage": "GETMe q_γ",
}


def load_group(data, group):
    measurements = []
    for path in sorted(glob.glob(os.path.join(data, "data", group, "*.json"))):
        with open(path) as f:
            measurements.append(json.load(f))
    return measurements


def by_mesh(measurements):
    meshes = {}
    for m in measurements:
        meshes.setdefault(m["mesh"], []).append(m)
    for rows in meshes.values():
        rows.sort(key=lambda m: (METHOD_ORDER.index(m["method"]) if m["method"] in METHOD_ORDER
                                 else 99, m.get("threads", 0), m.get("mode", "")))
    return meshes


def seconds(spread, digits=3):
    if not spread:
        return "–"
    if spread["min"] == spread["max"]:
        return f"{spread['median']:.{digits}f}"
    return f"{spread['median']:.{digits}f} ({spread['min']:.{digits}f}–{spread['max']:.{digits}f})"


def iterations(result):
    """Per phase, in order, like the paper's "26/11,500"; an untangle phase in brackets."""
    parts = []
    untangle = ""
    for phase in result["phases"]:
        if phase["phase"] == "untangle":
            untangle = f"({phase['iterations']:,}) "
        else:
            parts.append(f"{phase['iterations']:,}")
    return untangle + "/".join(parts)


def elements_text(m):
    names = {"tetrahedron": "tet", "hexahedron": "hex", "pyramid": "pyr", "prism": "prism"}
    counts = [f"{n:,} {names.get(t, t)}" for t, n in m["elements_by_type"].items() if n]
    return f"{m['elements']:,} elements: " + ", ".join(counts)


def reference_by_name():
    return {row["mesh"]: row for row in read_mesquite_reference()}


def reference_for(m, references):
    name = os.path.basename(m["spec"]) if m["source"] == "file" else m["mesh"]
    return references.get(name)


def quality_tables(measurements, references):
    """One table per mesh in the form of the paper's Tables 1–3."""
    out = []
    for mesh, rows in by_mesh(measurements).items():
        rows = [m for m in rows if m.get("mode") == "in-process" and m.get("threads") == 1]
        ok = [m for m in rows if "error" not in m]
        if not ok:
            continue
        first = ok[0]
        out.append(f"### {mesh} ({elements_text(first)})\n")
        out.append("| Method | Iter | Time (s) | q_min | q_mean | to 99 % of gain (s) | "
                   "to Mesquite q_mean − 0.005 (s) |")
        out.append("|---|---|---|---|---|---|---|")
        r = first["result"]
        out.append(f"| Initial | – | – | {r['q_min_before']:.4f} | {r['q_mean_before']:.4f} | | |")
        ref = reference_for(first, references)
        if ref:
            q_min = ref["q_min"] if ref["q_min"] != "-" else "–"
            q_mean = ref["q_mean"] if ref["q_mean"] != "-" else "–"
            note = "" if ref["q_mean"] != "-" else f" (issue 5, a ~{int(ref['elements']):,}-element mesh like it)"
            out.append(f"| Mesquite 2.99 feasible Newton{note} | – | {ref['seconds']} | {q_min} | "
                       f"{q_mean} | | |")
        for m in rows:
            label = METHOD_LABEL.get(m["method"], m["method"])
            if "error" in m:
                out.append(f"| {label} | failed: {m['error']} | | | | | |")
                continue
            r = m["result"]
            invalid = f" ({r['invalid']} invalid)" if r["invalid"] else ""
            out.append(f"| {label} | {iterations(r)} | {seconds(m['wall_seconds'])} | "
                       f"{r['q_min']:.4f}{invalid} | {r['q_mean']:.4f} | "
                       f"{seconds(m['seconds_to_99_percent_gain'])} | "
                       f"{seconds(m['seconds_to_target'])} |")
        out.append("")
    return "\n".join(out) if out else "_No data: run bench/run.sh._"


def warpage_table(measurements):
    """Table 4: mean ratio and warpage, for meshes with quadrilateral faces."""
    out = ["| Mesh | Method | q_min | q_mean | w_max | w_mean |", "|---|---|---|---|---|---|"]
    for mesh, rows in by_mesh(measurements).items():
        rows = [m for m in rows if m.get("mode") == "in-process" and m.get("threads") == 1
                and "error" not in m]
        if not rows or rows[0]["result"]["warpage_max_before"] == 0:
            continue
        r = rows[0]["result"]
        out.append(f"| {mesh} | Initial | {r['q_min_before']:.4f} | {r['q_mean_before']:.4f} | "
                   f"{r['warpage_max_before']:.4f} | {r['warpage_mean_before']:.4f} |")
        for m in rows:
            r = m["result"]
            out.append(f"| | {METHOD_LABEL.get(m['method'], m['method'])} | {r['q_min']:.4f} | "
                       f"{r['q_mean']:.4f} | {r['warpage_max']:.4f} | {r['warpage_mean']:.4f} |")
    return "\n".join(out) if len(out) > 2 else "_No data: run bench/run.sh._"


def phase_seconds(result, phase):
    return sum(p["seconds"] for p in result["phases"] if p["phase"] == phase)


def scaling_table(measurements):
    out = ["| mesh | elements | threads | iterations | simultaneous phase s | "
           "ns per element-iteration | vs smallest mesh | speed-up over 1 thread | "
           "same result as 1 thread | peak RSS MB | bytes per element: mesh / run |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    rows = sorted((m for m in measurements if "error" not in m and m["method"] == "simultaneous"
                   and m.get("mode") == "in-process"), key=lambda m: (m["elements"], m["threads"]))
    single = {m["mesh"]: m for m in rows if m["threads"] == 1}
    smallest = {}
    for m in rows:
        r = m["result"]
        phase = phase_seconds(r, "simultaneous")
        its = r["iterations_simultaneous"]
        ns = 1e9 * phase / (m["elements"] * its) if its else float("nan")
        smallest.setdefault(m["threads"], ns)
        one = single.get(m["mesh"])
        speedup = same = "–"
        if one and m["threads"] != 1:
            speedup = f"{phase_seconds(one['result'], 'simultaneous') / phase:.2f}×" if phase else "–"
            same = "yes" if (one["result"]["q_mean"] == r["q_mean"]
                             and one["result"]["q_min"] == r["q_min"]) else "**no**"
        rss = m["peak_rss_bytes"]["median"] if m["peak_rss_bytes"] else 0
        base = m.get("rss_before_load_bytes", 0)
        mesh_bytes = (m.get("rss_after_load_bytes", base) - base) / m["elements"]
        out.append(f"| {m['mesh']} | {m['elements']:,} | {m['threads']} | {its} | "
                   f"{phase:.3f} | {ns:.1f} | {ns / smallest[m['threads']]:.2f} | {speedup} | "
                   f"{same} | {rss / 1e6:.0f} | {mesh_bytes:.0f} / {(rss - base) / m['elements']:.0f} |")
    return "\n".join(out) if len(out) > 2 else "_No data: run bench/run.sh._"


def service_table(measurements):
    out = ["| mesh | elements | method | threads | in-process wall s | service wall s | overhead | "
           "first progress event s (service) | peak RSS MB in-process | peak RSS MB client / "
           "server |", "|---|---|---|---|---|---|---|---|---|---|"]
    local = {(m["mesh"], m["method"], m["threads"]): m for m in measurements
             if m.get("mode") == "in-process" and "error" not in m}
    for m in measurements:
        if m.get("mode") != "service" or "error" in m:
            continue
        base = local.get((m["mesh"], m["method"], m["threads"]))
        if not base:
            continue
        lw, sw = base["wall_seconds"]["median"], m["wall_seconds"]["median"]
        first = [r["first_event_wall_seconds"] for r in m["runs"]
                 if r["first_event_wall_seconds"] is not None]
        server = m["server_peak_rss_bytes"]["median"] / 1e6 if m["server_peak_rss_bytes"] else None
        out.append(f"| {m['mesh']} | {m['elements']:,} | {m['method']} | {m['threads']} | "
                   f"{seconds(base['wall_seconds'])} | {seconds(m['wall_seconds'])} | "
                   f"{100 * (sw / lw - 1):+.1f} % | "
                   f"{(sorted(first)[len(first) // 2] if first else float('nan')):.3f} | "
                   f"{base['peak_rss_bytes']['median'] / 1e6:.0f} | "
                   f"{m['peak_rss_bytes']['median'] / 1e6:.0f} / "
                   f"{'–' if server is None else f'{server:.0f}'} |")
    return "\n".join(out) if len(out) > 2 else "_No data: run bench/run.sh._"


def mesquite_table(measurements, references):
    out = ["| mesh | elements | Mesquite s | Mesquite q_mean | target q_mean | GETMe reaches it "
           "after (s) | share of Mesquite's time | ≤ 1/10 | GETMe full run s | GETMe final q_min / "
           "q_mean |", "|---|---|---|---|---|---|---|---|---|---|"]
    for m in measurements:
        if (m["method"] != "getme" or m.get("mode") != "in-process" or m.get("threads") != 1
                or "error" in m):
            continue
        ref = reference_for(m, references)
        if not ref:
            continue
        r = m["result"]
        mesquite_s = float(ref["seconds"])
        if ref["q_mean"] != "-":
            target = f"{m['target_q_mean']:.4f}" if m["target_q_mean"] is not None else "–"
            reach = m["seconds_to_target"]
            label = ""
        else:  # issue 5 gives only a time: compare GETMe's time to 99 % of its own gain
            target = "– (99 % of GETMe's gain)"
            reach = m["seconds_to_99_percent_gain"]
            label = " (generated like the paper's)"
        if reach:
            share = reach["median"] / mesquite_s
            reached = f"{seconds(reach)}"
            met = "yes" if share <= 0.1 else "**no**"
            share_text = f"{share:.3f}"
        else:
            reached, share_text, met = "not reached", "–", "**no**"
        out.append(f"| {m['mesh']}{label} | {m['elements']:,} | {ref['seconds']} | "
                   f"{ref['q_mean'] if ref['q_mean'] != '-' else '–'} | {target} | {reached} | "
                   f"{share_text} | {met} | {seconds(m['wall_seconds'])} | "
                   f"{r['q_min']:.4f} / {r['q_mean']:.4f} |")
    return "\n".join(out) if len(out) > 2 else "_No data: run bench/run.sh._"


def micro_table(data):
    files = sorted(glob.glob(os.path.join(data, "micro", "*.json")))
    if not files:
        return "_Not run: no micro-benchmark executable (build/bin/getme_micro_bench, bench/micro) was built._"
    standard = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads",
                "iterations", "real_time", "cpu_time", "time_unit", "aggregate_name",
                "family_index", "per_family_instance_index", "aggregate_unit", "label"}
    out = ["| executable | benchmark | real time | CPU time | counters |", "|---|---|---|---|---|"]
    for path in files:
        with open(path) as f:
            report = json.load(f)
        for b in report.get("benchmarks", []):
            if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
                continue
            counters = ", ".join(f"{k} {v:.4g}" for k, v in b.items()
                                 if k not in standard and isinstance(v, (int, float)))
            out.append(f"| {os.path.basename(path)[:-5]} | {b.get('run_name', b['name'])} | "
                       f"{b['real_time']:,.1f} {b['time_unit']} | {b['cpu_time']:,.1f} "
                       f"{b['time_unit']} | {counters} |")
    return "\n".join(out)


def header(machine):
    provisional = ("**Provisional** (a `--quick` run: small meshes, one repeat; the full run "
                   "replaces these numbers).\n\n"
                   if machine["mode"] == "quick" else "")
    load = machine.get("load_average_start", [0])[0], machine.get("load_average_end", [0])[0]
    return (f"{provisional}Measured {machine['date']}, commit `{machine['commit']}`, "
            f"`{machine['mode']}` run, {machine['repeats']} repeat(s) per measurement "
            f"(median, with min–max where repeated).\nMachine: {machine['cpu']}, "
            f"{machine['cores']} cores, {machine['memory_gb']} GB, {machine['os']}, kernel "
            f"{machine['kernel']}; {machine['compiler']}, CMake build type "
            f"{machine['build_type']}. Load average (1 min) {load[0]:.2f} at the start, "
            f"{load[1]:.2f} at the end."
            + (f" Scheduling: {machine['scheduling']}." if machine.get("scheduling") else "")
            + "".join(addendum(a) for a in machine.get("addenda", [])))


def addendum(run):
    """A later `run_benchmarks.py --only` run whose groups replaced the main run's."""
    load = run.get("load_average_start", [0])[0], run.get("load_average_end", [0])[0]
    words = run["command"].split()
    limit = ""
    if "--max-elements" in words[:-1]:
        limit = (f" (meshes up to {int(words[words.index('--max-elements') + 1]):,} elements; "
                 "larger ones are the main run's)")
    return (f"\n\nRe-run afterwards (`--only`): {', '.join(run['groups'])}{limit}, measured "
            f"{run['date']}, commit `{run['commit']}`, {run['repeats']} repeat(s); load average "
            f"{load[0]:.2f} at the start, {load[1]:.2f} at the end"
            + (f"; scheduling: {run['scheduling']}" if run.get("scheduling") else "") + ".")


def commands(machine):
    root = os.path.dirname(HERE) + "/"
    lines = ["```sh", machine["command"].replace(root, "")]
    lines += [command.replace(root, "") for command in machine["driver_commands"]]
    for run in machine.get("addenda", []):
        lines.append("# re-run afterwards:")
        lines.append(run["command"].replace(root, ""))
        lines += [command.replace(root, "") for command in run["driver_commands"]]
    lines.append("```")
    return "\n".join(lines)


def plots(data, doc_dir):
    out = []
    for path in sorted(glob.glob(os.path.join(data, "plots", "*.svg"))):
        rel = os.path.relpath(path, doc_dir)
        out.append(f"![{os.path.basename(path)[:-4]}]({rel})")
    return "\n\n".join(out) if out else "_No plots yet: run bench/run.sh._"


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    data, doc = sys.argv[1], sys.argv[2]
    with open(os.path.join(data, "machine.json")) as f:
        machine = json.load(f)
    references = reference_by_name()
    shared, generated = load_group(data, "shared"), load_group(data, "generated")
    scaling, service = load_group(data, "scaling"), load_group(data, "service")
    blocks = {
        "header": header(machine),
        "shared-tables": quality_tables(shared, references),
        "generated-tables": quality_tables(generated, references),
        "warpage": warpage_table(shared + generated),
        "mesquite": mesquite_table(shared + generated, references),
        "scaling": scaling_table(scaling),
        "service": service_table(service),
        "micro": micro_table(data),
        "plots": plots(data, os.path.dirname(os.path.abspath(doc))),
        "commands": commands(machine),
    }
    with open(doc) as f:
        text = f.read()
    for name, body in blocks.items():
        pattern = re.compile(rf"(<!-- BEGIN generated: {name} -->\n).*?(<!-- END generated: {name} -->)",
                             re.S)
        if not pattern.search(text):
            raise SystemExit(f"{doc}: no '<!-- BEGIN generated: {name} -->' … END block")
        text = pattern.sub(lambda match: match.group(1) + body + "\n" + match.group(2), text)
    with open(doc, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
