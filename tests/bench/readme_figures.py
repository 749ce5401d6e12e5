#!/usr/bin/python3
"""The docs' measured figures, made from the files the benchmarks write.

  /usr/bin/python3 tests/bench/readme_figures.py [--write] [--root DIR]

Each block of README.md or renderer/bench/README.md between '<!-- begin: figures NAME -->' and
'<!-- end: figures NAME -->' is made here from result files alone, never typed by hand:

  trade-fig9_14  assets/bench/fig9_14/bench.csv      (radview bench on fig. 9.14's scene)
  trade-cornell  assets/bench/cornell/bench.csv, .md (radview bench on the bundled solution)
  trade-cornell-truth  assets/bench/cornell-truth/bench.csv, .md (the same, against the path
                 tracer's true image)
  truth          tests/bench/results/truth/agreement.md (tests/truth/agreement_table.py)
  solution-noise tests/bench/results/solution_noise.md (tests/bench/solution_noise.py)
  noisy-solutions tests/bench/results/noisy_solutions.md (tests/bench/noisy_solutions.py)

tests/bench/regenerate_figures.sh runs those benchmarks and then this with --write. Without
--write it checks: exit 1 naming each block that differs from what the files give (a test runs
that), 2 for a missing file, or a block no document holds.
"""
import argparse
import csv
import math
import os
import re
import sys

PROGRAM = "readme_figures"


def fail(message, code=2):
    print("%s: %s" % (PROGRAM, message), file=sys.stderr)
    sys.exit(code)


def read_rows(path):
    if not os.path.isfile(path):
        fail("no %s: run tests/bench/regenerate_figures.sh" % path)
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def per_pixel(rows):
    return [r for r in rows if r["setting"].startswith("per pixel")]


def steps(value):
    return "%.3g" % float(value) if float(value) < 10 else "%.1f" % float(value)


def interval(row, prefix):
    """'estimate [low, high]' of a column family of bench.csv, with as many decimals as it takes
    for the interval to show (at least three significant digits, at most five decimals)."""
    names = {"error": ("error_estimate_steps", "error_ci_low_steps", "error_ci_high_steps"),
             "solution": ("solution_error_steps", "solution_ci_low_steps", "solution_ci_high_steps"),
             "reconstruction": ("reconstruction_error_steps", "reconstruction_ci_low_steps",
                                "reconstruction_ci_high_steps")}[prefix]
    value, low, high = (float(row[n]) for n in names)
    decimals = max(0, 2 - int(math.floor(math.log10(value)))) if value > 0 else 2
    while decimals < 5 and (round(low, decimals) == round(value, decimals) or
                            round(value, decimals) == round(high, decimals)):
        decimals += 1
    return "%.*f [%.*f, %.*f]" % (decimals, value, decimals, low, decimals, high)


def overlaps(a, b, prefix):
    low, high = ("%s_ci_low_steps" % prefix, "%s_ci_high_steps" % prefix)
    return float(a[low]) <= float(b[high]) and float(b[low]) <= float(a[high])


def label(row):
    relaxed = "" if "C0 not relaxed" not in row["setting"] else ", C0 not relaxed"
    return row["method"] + relaxed


def tie_groups(rows, prefix):
    """Rows in order of their estimate, each with the rows after it whose interval overlaps its own
    folded in (a tie), as (the fastest of them, [labels of the others])."""
    key = prefix + ("_estimate_steps" if prefix == "error" else "_error_steps")
    ordered = sorted(rows, key=lambda r: float(r[key]))
    groups, used = [], set()
    for i, r in enumerate(ordered):
        if id(r) in used:
            continue
        tied = [r] + [s for s in ordered[i + 1:] if id(s) not in used and overlaps(r, s, prefix)]
        used.update(id(s) for s in tied)
        fastest = min(tied, key=lambda s: float(s["frame_ms"]))
        groups.append((fastest, [label(s) for s in tied if s is not fastest]))
    return groups


def ms(value):
    v = float(value)
    return "%.3g" % v if v < 1000 else "%.0f" % v


def trade_fig9_14(root):
    rows = read_rows(os.path.join(root, "assets/bench/fig9_14/bench.csv"))
    lines = ["| per pixel, by the method's part | frame ms | error, steps [95 %] | the solution's part | "
             "the method's part |", "|---|---|---|---|---|"]
    for r, tied in tie_groups(per_pixel(rows), "reconstruction"):
        name = label(r) + (" (%s the same)" % ", ".join(tied) if tied else "")
        lines.append("| %s | %s | %s | %s | %s |" % (name, ms(r["frame_ms"]), interval(r, "error"),
                                                     steps(r["solution_error_steps"]), interval(r, "reconstruction")))
    # What tessellation costs for the same picture: each level's rows against their per-pixel row.
    exact = {label(r): float(r["error_estimate_steps"]) for r in per_pixel(rows)}
    parts = []
    for level in (16, 64):
        at = [r for r in rows if re.match(r"level %d(,|$)" % level, r["setting"])]
        if not at:
            continue
        frames = [float(r["frame_ms"]) for r in at]
        apart = max(abs(float(r["error_estimate_steps"]) - exact[label(r)]) for r in at)
        parts.append("%s-%s ms at level %d (errors within %.2g steps of per pixel)" % (
            ms(min(frames)), ms(max(frames)), level, apart))
    if parts:
        lines += ["", "Tessellated, the same methods take " + " and ".join(parts) + "."]
    return lines


def bench_header(path, pattern, what):
    with open(path) as f:
        text = f.read()
    found = re.search(pattern, text)
    if not found:
        fail("%s: no %s in its header" % (path, what))
    return found


def trade_cornell(root):
    folder = os.path.join(root, "assets/bench/cornell")
    rows = read_rows(os.path.join(folder, "bench.csv"))
    md = os.path.join(folder, "bench.md")
    size = bench_header(md, r": (\d+x\d+), camera", "image size").group(1)
    reference = bench_header(md, r"at each pixel's centre, (\d+) spp in (\d+) independent runs, ([\d.]+) s; its noise "
                             r"\(RMS, over the compared pixels\) [^,]+ linear, ([\d.]+) display steps", "reference")
    nodes = bench_header(md, r"(\d+) spp each \(--node-spp", "nodal reference")
    whole = bench_header(md, r"Whole bench: ([\d.]+) s", "total time")
    lines = ["At %s, %s spp in %s runs and %s per node, the whole bench %s s:" % (
        size, reference.group(1), reference.group(2), nodes.group(1), whole.group(1)), "",
        "| per pixel, by error | ms | error, steps [95 %] | the solution's part | the reconstruction's part |",
        "|---|---|---|---|---|"]
    for r, tied in tie_groups(per_pixel(rows), "error"):
        name = label(r) + (" (%s tie with it)" % ", ".join(tied) if tied else "")
        lines.append("| %s | %s | %s | %s | %s |" % (name, ms(r["frame_ms"]), interval(r, "error"),
                                                     steps(r["solution_error_steps"]), interval(r, "reconstruction")))
    lines.append("| reference: the final gather, noise %s steps | %s s | | | |" % (reference.group(4),
                                                                                   reference.group(3)))
    return lines


def trade_cornell_truth(root):
    folder = os.path.join(root, "assets/bench/cornell-truth")
    rows = read_rows(os.path.join(folder, "bench.csv"))
    md = os.path.join(folder, "bench.md")
    size = bench_header(md, r": (\d+x\d+), camera", "image size").group(1)
    reference = bench_header(md, r"true image \(no solution used\) at each pixel's centre, (\d+) spp in (\d+) "
                             r"independent runs, ([\d.]+) s; its noise \(RMS, over the compared pixels\) [^,]+ linear, "
                             r"([\d.]+) display steps", "reference")
    lines = ["At %s, the path tracer at %s spp in %s runs:" % (size, reference.group(1), reference.group(2)), "",
             "| per pixel, by error | error, steps [95 %] | the solution's part | the reconstruction's part | time |",
             "|---|---|---|---|---|"]
    gl_rows = [r for r in per_pixel(rows) if r["solution_error_steps"]]
    for r, tied in tie_groups(gl_rows, "error"):
        name = label(r) + (" (%s tie with it)" % ", ".join(tied) if tied else "")
        lines.append("| %s | %s | %s | %s | %s ms |" % (name, interval(r, "error"), interval(r, "solution"),
                                                        interval(r, "reconstruction"), ms(r["frame_ms"])))
    for r in per_pixel(rows):
        if not r["solution_error_steps"]:  # the final gather's row: a CPU time, in seconds
            lines.append("| %s, %s | %s | | | %.1f s |" % (r["method"], r["setting"].split(", ", 1)[-1],
                                                            interval(r, "error"), float(r["frame_ms"]) / 1000))
    lines.append("| reference: path tracer, noise %s steps | | | | %s s |" % (reference.group(4), reference.group(3)))
    return lines


def truth(root):
    path = os.path.join(root, "tests/bench/results/truth/agreement.md")
    if not os.path.isfile(path):
        fail("no %s: run tests/bench/regenerate_figures.sh truth" % path)
    with open(path) as f:
        text = f.read().splitlines()
    lines = [text[0], "", "| radview image | worst surface (ratio to the truth) | every surface within | "
             "relative RMSE | time |", "|---|---|---|---|---|"]
    row = re.compile(r"^\| \d+\. (.*?) \| (.*?) \[([\d.]+), ([\d.]+)\] \| (.*?) \| ([\d.]+ %) \(raw [^)]*\) \| "
                     r"([\d.]+ s).* \|$")
    count = 0
    for line in text:
        m = row.match(line)
        if not m:
            continue
        count += 1
        name, worst, low, high, within, rmse, seconds = m.groups()
        ratio = worst.rsplit(" ", 1)[1]
        # An interval is shown where the row's own noise was estimated; exact rows have none.
        worst_cell = worst if low == high == ratio else "%s [%s, %s]" % (worst, low, high)
        lines.append("| %s | %s | %s | %s | %s |" % (name, worst_cell, within, rmse, seconds))
    if count == 0:
        fail("%s: no rows in its table" % path)
    return lines


def result_table(root, name, part):
    """A result file that is already the table, as it is."""
    path = os.path.join(root, "tests/bench/results", name)
    if not os.path.isfile(path):
        fail("no %s: run tests/bench/regenerate_figures.sh %s" % (path, part))
    with open(path) as f:
        return f.read().rstrip("\n").split("\n")


def solution_noise(root):
    return result_table(root, "solution_noise.md", "noise")


def noisy_solutions(root):
    return result_table(root, "noisy_solutions.md", "noisy")


BLOCKS = {"trade-fig9_14": trade_fig9_14, "trade-cornell": trade_cornell, "trade-cornell-truth": trade_cornell_truth,
          "truth": truth, "solution-noise": solution_noise, "noisy-solutions": noisy_solutions}
DOCS = ["README.md", "renderer/bench/README.md"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--write", action="store_true", help="rewrite README's blocks (default: check them)")
    p.add_argument("--root", default=os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..")))
    args = p.parse_args()
    texts, stale, found = {}, [], set()
    for doc in DOCS:
        path = os.path.join(args.root, doc)
        with open(path) as f:
            text = f.read()
        for name, make in BLOCKS.items():
            begin, end = "<!-- begin: figures %s -->\n" % name, "<!-- end: figures %s -->" % name
            if begin not in text or end not in text:
                continue
            found.add(name)
            start = text.index(begin) + len(begin)
            stop = text.index(end)
            wanted = "\n".join(make(args.root)) + "\n"
            if text[start:stop] != wanted:
                stale.append("%s in %s" % (name, doc))
                text = text[:start] + wanted + text[stop:]
        texts[path] = text
    missing = sorted(set(BLOCKS) - found)
    if missing:
        fail("no document holds the block%s %s" % ("s" if len(missing) > 1 else "", ", ".join(missing)))
    if args.write:
        for path, text in texts.items():
            with open(path, "w") as f:
                f.write(text)
        print("%s: %s" % (PROGRAM, "rewrote " + ", ".join(stale) if stale else "the docs are already current"))
        return 0
    if stale:
        fail("the docs' figures differ from the result files in: %s (tests/bench/readme_figures.py --write "
             "rewrites them)" % ", ".join(stale), 1)
    print("%s: the docs' figures are the result files'" % PROGRAM)
    return 0


if __name__ == "__main__":
    sys.exit(main())
