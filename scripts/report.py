#!/usr/bin/python3
"""One self-contained HTML report of a heavesim result file (docs/report.md): the case,
the model, the build's validation status, the design quantities, every channel's
statistics, the compensator, the joint design loads and the figures, plots embedded as
base64 PNG, no external file, script, style or font (it opens offline from file://).

    heavesim report OUT.h5 [-o report.html] [--duration S] [--from S] [--validation LOG]
    /usr/bin/python3 scripts/report.py OUT.h5 --heavesim build/heavesim [...]

Where the numbers come from: the file's attributes and /summary (docs/result-file.md),
the statistics from `heavesim stats --json` over the window and duration asked for (the
same code that wrote the file's `statistics` attributes; docs/physics/statistics.md),
the figures from scripts/plot_run.py and scripts/plot_reaction_envelope.py. The file is
read through the heavesim package (docs/python.md).

Exit codes: 0 written; 2 bad input (a missing file, not HDF5, not a heavesim result, a bad
--duration, --from or --validation), the message naming the file, what was found and
what was expected; 1 anything else. A run that stopped (complete = 0, an exit-3 run)
gets a report with a banner that says so, with the failure time and diagnosis.
"""
import argparse
import base64
import datetime
import html
import json
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import yaml

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))
try:
    import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python
except ImportError:
    # A build without the compiled module (the sanitizer build): reading needs only the
    # package's Python files (docs/python.md), which the source tree has.
    sys.path.insert(0, str(HERE.parent / "python"))
    import heavesim  # noqa: E402
import plot_reaction_envelope  # noqa: E402  the figures: one copy of the plotting rules
import plot_run  # noqa: E402
from plot_run import NOTHING, case_model, engineering_scale  # noqa: E402
from heavesim import rao  # noqa: E402  RAO tables of `heavesim rao` (docs/rao.md)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import scipy.signal  # noqa: E402

RESULT_KIND = "a heavesim result file (HDF5)"
DEFAULT_DURATION = 10800.0  # s: the 3-hour most probable maximum
# The statistics table's columns: (field of stats::statistic_fields(), heading, unit: "u"
# the channel's, "s", "-" or "count").
STATISTIC_COLUMNS = [
    ("window_mean", "mean", "u"), ("window_standard_deviation", "std", "u"),
    ("window_minimum", "min", "u"), ("window_maximum", "max", "u"),
    ("skewness", "skew", "-"), ("kurtosis", "kurt", "-"),
    ("zero_upcrossing_period", "Tz", "s"), ("upcrossings", "up-x", "count"),
    ("significant_crest", "sig. crest", "u"), ("significant_trough", "sig. trough", "u"),
    ("mean_plus_4_sigma", "mean+4σ", "u"), ("mpm_rayleigh", "MPM rec. Rayleigh", "u"),
    ("mpm_rayleigh_duration", "MPM D Rayleigh", "u"), ("mpm_weibull_duration", "MPM D Weibull", "u"),
    ("weibull_shape", "Weibull k", "-"), ("weibull_ks_statistic", "Weibull KS", "-"),
    ("mpm_pareto_duration", "MPM D GPD", "u"), ("pareto_ks_statistic", "GPD KS", "-"),
    ("spectral_peak_period", "Tp", "s"), ("spectral_m0", "m0", "u²"),
    ("spectral_m2", "m2", "u² Hz²"), ("spectral_m4", "m4", "u² Hz⁴"),
    ("spectral_bandwidth", "ε", "-"),
]


class BadInput(Exception):
    """Exit 2: `file`, the key path inside it, what was found and what was expected."""

    def __init__(self, file, key, found, expected):
        where = f"{file}: {key}: " if key else f"{file}: "
        super().__init__(f"{where}found {found}; expected {expected}")


# --- reading ---------------------------------------------------------------------------

def open_result(path):
    """The heavesim.Result of `path`, or BadInput saying why it is not a heavesim result."""
    if not os.path.exists(path):
        raise BadInput(path, "", "a path that does not exist", RESULT_KIND)
    if not os.path.isfile(path):
        raise BadInput(path, "", "a directory or device, not a regular file", RESULT_KIND)
    if not h5py.is_hdf5(path):
        raise BadInput(path, "", "a file that is not an HDF5 file (no HDF5 signature)", RESULT_KIND)
    result = heavesim.open(path)
    if "heavesim_version" not in result.attributes:
        result.close()
        raise BadInput(path, "/", "an HDF5 file without the root attribute heavesim_version",
                       f"{RESULT_KIND}, as `heavesim run` writes it (docs/result-file.md)")
    if "time" not in result:
        result.close()
        raise BadInput(path, "/time", "no such dataset", f"the dataset /time of {RESULT_KIND}")
    return result


def run_stats(binary, path, duration, start):
    """`heavesim stats --json` of every channel: {(channel, column): {field: value}}, the
    window start [s] it used and its message when it could not (fewer than 2 samples)."""
    command = [binary, "stats", path, "--json", "--duration", repr(duration)]
    if start is not None:
        command += ["--after", repr(start)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        return {}, start, done.stderr.strip()
    answer = json.loads(done.stdout)
    table = {(item["channel"], item["column"]): item["statistics"] for item in answer["channels"]}
    return table, answer["window_start"], ""


# --- HTML helpers ----------------------------------------------------------------------

def number(value, digits=6):
    """A value as text (NaN/None as "–") and its full-precision data-value."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–", ""
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return f"{value}", f"{value}"
    return f"{value:.{digits}g}", f"{float(value):.17g}"


def cell(value, digits=6):
    text, exact = number(value, digits)
    return f'<td data-value="{exact}">{text}</td>' if exact else "<td>–</td>"


def table(table_id, headings, rows, caption=""):
    """rows: lists of already-made <td>/<th> cells."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headings)
    body = "\n".join(f"<tr>{''.join(row)}</tr>" for row in rows)
    caption = f"<caption>{caption}</caption>" if caption else ""
    return f'<table id="{table_id}">{caption}<thead><tr>{head}</tr></thead><tbody>\n{body}\n</tbody></table>'


def text_cell(text):
    return f"<td>{html.escape(str(text))}</td>"


def embed_png(path, alt):
    with open(path, "rb") as image:
        data = base64.b64encode(image.read()).decode("ascii")
    return f'<figure><img alt="{html.escape(alt)}" src="data:image/png;base64,{data}"><figcaption>{html.escape(alt)}</figcaption></figure>'


def figure_png(fig, directory, name):
    path = os.path.join(directory, name)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


# --- sections --------------------------------------------------------------------------

def failure_banner(r):
    if r.complete:
        return ""
    attributes = r.attributes
    if "failure" in attributes:
        what = (f"The run failed at t = {attributes.get('failure_time', float('nan')):.6g} s: "
                f"{attributes['failure']}. Suggestion: {attributes.get('failure_suggestion', '–')}")
    else:
        what = "The run stopped before its end (signal, write failure or a writer still running)."
    return (f'<div id="incomplete" class="banner" data-failure-time="{number(attributes.get("failure_time"))[1]}">'
            f"<strong>INCOMPLETE RESULT</strong> (complete = 0, {r.samples} samples written). {html.escape(what)} "
            "Every number below is over what was written, not over the case's t_end.</div>")


def summary_section(r, case, window_start, duration):
    attributes, summary = r.attributes, r.summary
    time = r.time
    solver = case.get("solver", {}) if isinstance(case.get("solver"), dict) else {}
    solver_text = ", ".join(f"{k} {v}" for k, v in solver.items()) or "–"
    rows = [
        ("case", f"{attributes.get('case_name', '?')} ({attributes.get('case_file', '?')})"),
        ("description", case.get("description", "–")),
        ("case SHA-256 (resolved YAML)", attributes.get("case_sha256", "–")),
        ("heavesim version (writer)", attributes.get("heavesim_version", "–")),
        ("written (UTC)", attributes.get("created_utc", "–")),
        ("analysis", attributes.get("analysis", "time-domain run")),
        ("solver", solver_text),
        ("t_end asked [s]", solver.get("t_end", "–")),
        ("time span written [s]", f"{time[0]:.6g} .. {time[-1]:.6g}" if len(time) else "–"),
        ("samples written", r.samples),
        ("complete", "yes" if r.complete else "NO (see the banner)"),
        ("evaluation window start [s]", f"{window_start:.6g}" if window_start is not None else "–"),
        ("MPM duration D [s]", f"{duration:.6g}"),
        ("wall time [s]", number(summary.get("wall_time_s"))[0]),
        ("real-time factor", number(summary.get("real_time_factor"))[0]),
        ("integrator steps", summary.get("integrator_steps", "–")),
        ("relative energy change / drift",
         number(summary.get("relative_energy_drift", summary.get("relative_energy_change")))[0]),
    ]
    body = table("case-summary", ["item", "value"], [[f"<th>{html.escape(k)}</th>", text_cell(v)] for k, v in rows])
    return f"<section><h2>Case summary</h2>{body}</section>"


def model_section(r, case):
    parts = ["<section><h2>Model</h2><p>As the run read it (the resolved case stored in /case/yaml; "
             "expressions as written, parameters below).</p>"]
    bodies = [b for b in case.get("bodies", []) if isinstance(b, dict)]
    parts.append(table("model-bodies", ["body", "mass [kg]", "description"],
                       [[text_cell(b.get("name")), text_cell(b.get("mass")), text_cell(b.get("description", ""))]
                        for b in bodies], "bodies"))
    joints = [j for j in case.get("joints", []) if isinstance(j, dict)]
    parts.append(table("model-joints", ["joint", "type", "parent", "child", "description"],
                       [[text_cell(j.get(k, "")) for k in ("name", "type", "parent", "child", "description")]
                        for j in joints], "joints (tree)"))
    for key, title in (("loop_joints", "loop joints"), ("constraints", "constraints"), ("drivers", "drivers"),
                       ("forces", "force elements")):
        items = [item for item in case.get(key, []) if isinstance(item, dict)]
        if not items:
            continue
        rows = []
        for item in items:
            acts = item.get("body") or item.get("joint") or ""
            if not acts and isinstance(item.get("stroke"), dict):
                acts = "stroke: " + ", ".join(f"{k} {v}" for k, v in item["stroke"].items())
            if not acts:
                acts = " → ".join(str(item[k]) for k in ("parent", "child", "body_a", "body_b") if k in item)
            rows.append([text_cell(item.get("name", "")), text_cell(item.get("type", "")), text_cell(acts)])
        parts.append(table(f"model-{key.replace('_', '-')}", ["name", "type", "acts on"], rows, title))
    parameters = case.get("parameters", {})
    if isinstance(parameters, dict) and parameters:
        parts.append("<details><summary>parameters</summary>" + table(
            "model-parameters", ["name", "value"], [[text_cell(k), text_cell(v)] for k, v in parameters.items()]) +
            "</details>")
    if r.case_yaml:
        parts.append(f"<details><summary>resolved case (YAML)</summary><pre>{html.escape(r.case_yaml)}</pre></details>")
    parts.append("</section>")
    return "".join(parts)


def validation_section(binary, r, log_path):
    """What this build can say without running the suite: its version against the
    writer's, its checks, and a saved `heavesim validate` table when given."""
    version = subprocess.run([binary, "--version"], capture_output=True, text=True).stdout.strip()
    listing = subprocess.run([binary, "validate", "--list"], capture_output=True, text=True).stdout.splitlines()
    checks = [line.split(None, 1) for line in listing if line.strip()]
    writer = str(r.attributes.get("heavesim_version", "?"))
    same = "the same version" if version.endswith(writer) else f"NOT the writer's version ({writer})"
    parts = [f"<section><h2>Validation status of the build</h2><p>This report was made by "
             f"<code>{html.escape(version)}</code>, {same}. Its validation suite has {len(checks)} checks "
             "(docs/validation.md); run them with <code>heavesim validate</code> (a PASS/FAIL table; exit 0 only "
             "when every row passes) and pass its output with <code>--validation LOG</code> to have it here.</p>"]
    if log_path:
        # A row starts with a check's id and ends with PASS or FAIL ("FAIL (why)" for a check
        # that did not run); the closing "N validation rows FAIL" line is not a row.
        ids = {check[0] for check in checks}
        text = log_path.read_text()
        rows = [line for line in text.splitlines()
                if line.split()[:1] and line.split()[0] in ids and re.search(r"\s(PASS|FAIL)(\s*$|\s+\()", line)]
        passed = sum(bool(re.search(r"\sPASS\s*$", line)) for line in rows)
        status = "all PASS" if rows and passed == len(rows) else f"{len(rows) - passed} FAIL"
        parts.append(f'<p id="validation-log" data-rows="{len(rows)}" data-passed="{passed}">Saved table '
                     f"{html.escape(str(log_path))}: {len(rows)} rows, {passed} PASS: <strong>{status}</strong>.</p>"
                     f"<details><summary>the table</summary><pre>{html.escape(text)}</pre></details>")
    parts.append("<details><summary>the checks</summary>" +
                 table("validation-checks", ["id", "check"], [[text_cell(c[0]), text_cell(c[1] if len(c) > 1 else "")]
                                                              for c in checks]) + "</details>")
    parts.append("</section>")
    return "".join(parts)


def compensators(r, case):
    """[(name, stroke joint or None)] of the compensators the summary has headlines for."""
    names = sorted({key[: -len("_stroke_min_m")] for key in r.summary if key.endswith("_stroke_min_m")})
    joints = {}
    for item in case.get("forces", []):
        if isinstance(item, dict) and isinstance(item.get("stroke"), dict):
            joints[item.get("name")] = item["stroke"].get("joint")
    return [(name, joints.get(name)) for name in names]


def design_section(r, case, stats):
    """The design quantities of docs/result-file.md, "Design quantities"."""
    summary = r.summary
    rows = []

    def add(quantity, source, statistics, unit):
        if not statistics:
            return
        rows.append([f"<th>{html.escape(quantity)}</th>", text_cell(source), text_cell(unit)] +
                    [cell(statistics.get(field)) for field in ("window_mean", "window_standard_deviation",
                                                               "window_minimum", "window_maximum",
                                                               "mpm_rayleigh_duration", "mpm_weibull_duration")])

    add("hook load", "joints/td_string/reaction_force z", stats.get(("/joints/td_string/reaction_force", 2)), "N")
    found = compensators(r, case)
    for name, joint in found:
        if joint and f"reaction_force_{joint}_mean_N" in summary:
            rows.append([f"<th>compensator load ({html.escape(name)})</th>",
                         text_cell(f"|joints/{joint}/reaction_force| (summary)"), text_cell("N"),
                         cell(summary.get(f"reaction_force_{joint}_mean_N")),
                         cell(summary.get(f"reaction_force_{joint}_std_N")),
                         cell(summary.get(f"reaction_force_{joint}_min_N")),
                         cell(summary.get(f"reaction_force_{joint}_max_N")), "<td>–</td>", "<td>–</td>"])
        add(f"stroke ({name})", f"forces/{name}/stroke", stats.get((f"/forces/{name}/stroke", 0)), "m")
    for name in plot_run.contact_elements(r):
        add(f"weight on bit ({name})", f"forces/{name}/force", stats.get((f"/forces/{name}/force", 0)), "N")
    headings = ["quantity", "dataset", "unit", "mean", "std", "min", "max", "MPM D Rayleigh", "MPM D Weibull"]
    body = table("design-quantities", headings, rows) if rows else "<p>No design quantity in this file.</p>"
    efficiencies = [f"<li>{html.escape(name)}: η = {summary[name + '_efficiency']:.4f}</li>"
                    for name, _ in found if f"{name}_efficiency" in summary]
    return ("<section><h2>Design quantities</h2><p>Definitions: docs/result-file.md, \"Design quantities\". "
            "Statistics over the evaluation window; MPM over D.</p>" + body +
            (f"<ul>{''.join(efficiencies)}</ul>" if efficiencies else "") + "</section>")


def compensator_section(r, case, directory):
    found = compensators(r, case)
    if not found:
        return ""
    summary = r.summary
    fields = [("efficiency", "-"), ("base_heave_std_m", "m"), ("load_heave_std_m", "m"), ("stroke_min_m", "m"),
              ("stroke_max_m", "m"), ("end_stop_events_lower", "count"), ("end_stop_events_upper", "count"),
              ("end_stop_max_penetration_m", "m"), ("gas_pressure_min_Pa", "Pa"), ("gas_pressure_max_Pa", "Pa"),
              ("force_max_abs_N", "N"), ("control_error_max_abs_m", "m")]
    # One row per /summary headline <name>_<field>, one column per compensator.
    rows = [[f"<th>{html.escape(field)}</th>", text_cell(unit)] + [cell(summary.get(f"{name}_{field}"))
                                                                  for name, _ in found]
            for field, unit in fields if any(f"{name}_{field}" in summary for name, _ in found)]
    parts = ["<section><h2>Compensators: efficiency and stroke envelope</h2>",
             table("compensators", ["/summary headline", "unit"] + [name for name, _ in found], rows,
                   "η = 1 − σ(z_load)/σ(z_base) over the evaluation window; stroke from mid-stroke, + rods out")]
    strokes = [name for name, _ in found if f"forces/{name}/stroke" in r]
    if strokes:
        fig, ax = plt.subplots(figsize=(9, 3.2))
        for name in strokes:
            ax.plot(r.time, r[f"forces/{name}/stroke"], lw=0.8, label=f"{name} stroke")
            for bound in ("stroke_min_m", "stroke_max_m"):
                if f"{name}_{bound}" in summary:
                    ax.axhline(summary[f"{name}_{bound}"], ls="--", lw=0.6, color="grey")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("stroke [m]")
        ax.set_title("stroke history with its min/max (dashed)", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
        parts.append(embed_png(figure_png(fig, directory, "stroke.png"), "compensator stroke and its envelope"))
    parts.append("</section>")
    return "".join(parts)


def joint_loads_section(r, stats, duration):
    """Mean, dynamic amplitude (largest departure from the mean in the window) and the
    Rayleigh MPM over D, per component, joint frame and world frame."""
    joints = [name for name in r.joints if f"joints/{name}/reaction_force" in r]
    scale = max([abs(stats.get((f"/joints/{n}/reaction_force", c), {}).get(f) or 0.0)
                 for n in joints for c in range(3) for f in ("window_minimum", "window_maximum")] + [0.0])
    rows, idle, zero = [], [], 0
    for name in joints:
        peak = max(abs(stats.get((f"/joints/{name}/reaction_force", c), {}).get(f) or 0.0)
                   for c in range(3) for f in ("window_minimum", "window_maximum"))
        if peak <= NOTHING * scale:
            idle.append(name)
            continue
        for frame, suffix in (("joint", "_joint"), ("world", "")):
            for kind, unit, labels in (("force", "N", "xyz"), ("moment", "N m", "xyz")):
                path = f"/joints/{name}/reaction_{kind}{suffix}"
                for c, axis in enumerate(labels):
                    s = stats.get((path, c))
                    if not s:
                        continue
                    # A component below 1e-6 of the largest force (moments: times 1 m) is
                    # round-off or a free direction: counted, not listed (plot_run's rule).
                    if max(abs(s.get("window_minimum") or 0.0), abs(s.get("window_maximum") or 0.0)) <= NOTHING * scale:
                        zero += 1
                        continue
                    mean = s.get("window_mean")
                    amplitude = None
                    if mean is not None and s.get("window_maximum") is not None:
                        amplitude = max(s["window_maximum"] - mean, mean - s["window_minimum"])
                    rows.append([text_cell(name), text_cell(frame), text_cell(f"{'F' if kind == 'force' else 'M'}{axis}"),
                                 text_cell(unit), cell(mean), cell(amplitude), cell(s.get("window_standard_deviation")),
                                 cell(s.get("mpm_rayleigh_duration")), cell(s.get("mpm_minimum_rayleigh_duration"))])
    note = (f"<p>Carry nothing (&lt; 1e-6 of the largest load), not listed: {html.escape(', '.join(idle))}.</p>"
            if idle else "")
    if zero:
        note += (f"<p>{zero} components of the joints listed are below 1e-6 of the largest load (zero by the "
                 "joint's kind and the loading, or round-off) and are not listed.</p>")
    return ("<section><h2>Joint design loads</h2><p>The wrench the parent passes to the child at the joint origin "
            "(docs/result-file.md, \"What a joint reaction is\"), in the joint frame and in world axes; dynamic "
            f"amplitude = largest departure from the window mean; MPM over D = {duration:g} s (Rayleigh, maximum and "
            "minimum).</p>" + note +
            table("joint-loads", ["joint", "frame", "component", "unit", "mean", "dynamic amplitude", "std",
                                  "MPM max (D)", "MPM min (D)"], rows) + "</section>")


def statistics_section(r, stats, message):
    if not stats:
        return f"<section><h2>Statistics of every channel</h2><p>No statistics: {html.escape(message)}</p></section>"
    rows = []
    for (path, column), s in sorted(stats.items()):
        channel = r.channel(path)
        units = channel.units
        label = path if len(channel.shape) == 1 else f"{path}[{column}]"
        row = [text_cell(label), text_cell(units)]
        for field, _, _ in STATISTIC_COLUMNS:
            row.append(cell(s.get(field), 5))
        rows.append(row)
    headings = ["channel", "units"] + [f"{heading} [{unit}]" if unit not in ("-", "count") else heading
                                       for _, heading, unit in STATISTIC_COLUMNS]
    return ("<section><h2>Statistics of every channel</h2><p>Over the evaluation window; u is the channel's unit; "
            "definitions in docs/physics/statistics.md and docs/result-file.md (\"Response statistics\"). "
            "– : the statistic does not exist (a constant channel has no crossings; a fit needs 10 crests).</p>"
            + table("channel-statistics", headings, rows) + "</section>")


def spectra_figure(r, stats, window_start, directory):
    """Welch densities (scipy.signal.welch with the recorder's settings, docs/physics/statistics.md
    §5) of the hook load and the strokes, with the Tp the statistics give."""
    picks = [("/joints/td_string/reaction_force", 2, "hook load")]
    picks += [(f"/forces/{path.split('/')[2]}/stroke", 0, f"{path.split('/')[2]} stroke")
              for path in r.channels if re.fullmatch(r"/forces/[^/]+/stroke", path)]
    picks = [p for p in picks if p[0] in r.channels]
    window = r.time >= (window_start if window_start is not None else -math.inf)
    if not picks or np.count_nonzero(window) < 64:
        return ""
    dt = float(np.median(np.diff(r.time)))
    fig, axes = plt.subplots(len(picks), 1, figsize=(9, 2.6 * len(picks) + 0.4), squeeze=False)
    for ax, (path, column, label) in zip(axes[:, 0], picks):
        values = np.atleast_2d(r[path].T).T[window, column]
        length = min(4096, 2 ** int(math.floor(math.log2(max(len(values) // 4, 4)))))
        frequency, density = scipy.signal.welch(values, fs=1.0 / dt, nperseg=length)
        units = r.channel(path).units
        factor, shown = engineering_scale(units, math.sqrt(max(float(np.max(density)), 1e-300)))
        ax.semilogy(frequency[1:], density[1:] / factor ** 2, lw=0.9)
        tp = (stats.get((path, column)) or {}).get("spectral_peak_period")
        if tp:
            ax.axvline(1.0 / tp, color="C3", ls="--", lw=0.8, label=f"Tp = {tp:.3g} s (statistics)")
            ax.legend(fontsize=7, loc="upper right")
        ax.set_xlim(0.0, min(0.5 / dt, 1.0))
        ax.set_ylabel(f"S [{shown}²/Hz]")
        ax.set_title(f"{label}: one-sided Welch density (Hann, 50 % overlap, L = {length})", fontsize=9, loc="left")
        ax.grid(True, alpha=0.3, which="both")
    axes[-1, 0].set_xlabel("frequency [Hz]")
    return embed_png(figure_png(fig, directory, "spectra.png"), "spectral densities over the evaluation window")


def figures_section(r, stats, window_start, directory):
    stem = os.path.splitext(os.path.basename(r.path))[0]
    parts = ["<section><h2>Figures</h2>"]
    captions = {"joints": "joint coordinates and speeds", "reactions": "loads of joints, loops and drivers",
                "energy": "energy"}
    for plot, kind in ((plot_run.plot_joints, "joints"), (plot_run.plot_reactions, "reactions"),
                       (plot_run.plot_energy, "energy")):
        path = plot(r, r.time, stem, directory)
        if path:
            parts.append(embed_png(path, captions[kind]))
    # The envelope leaves out joints that carry nothing by itself (plot_reaction_envelope's
    # rule); a run that stopped before its window has only the record to show.
    in_window = window_start is not None and bool(np.any(r.time >= window_start))
    envelope = plot_reaction_envelope.plot_envelope(r, directory, stem, window_start if in_window else -math.inf)
    if envelope:
        parts.append(embed_png(envelope[0], "joint reaction envelopes over the " +
                               ("evaluation window" if in_window else "whole record") + " (joint frames)"))
    parts.append(spectra_figure(r, stats, window_start, directory))
    parts.append("</section>")
    return "".join(parts)


def rao_section(binary, r, case, directory):
    """The platform's RAOs from this run when it is an irregular sea whose wave elevation
    was recorded: `heavesim rao RESULT.h5` (H1 with coherence over the evaluation window,
    beside the frequency-domain RAO of the case's BEM data; docs/rao.md), its figure and
    a table of each mode's peak and its agreement with the frequency domain where the
    coherence is above 0.9. "" for regular waves or calm water (one frequency or none:
    nothing to estimate a transfer function from; a regular sweep is `heavesim rao CASE`)."""
    waves = case.get("waves")
    if not isinstance(waves, dict) or str(waves.get("type", "regular")) == "regular":
        return ""
    if not any(str(path).endswith("/wave_elevation") for path in r.channels):
        return ""
    out = os.path.join(directory, "rao")
    done = subprocess.run([binary, "rao", r.path, "-o", out, "--no-plot", "-q"], capture_output=True, text=True)
    parts = ['<section id="rao"><h2>RAOs from this run (H1)</h2>']
    if done.returncode != 0:
        parts.append(f"<p>heavesim rao could not estimate them: {html.escape(done.stderr.strip())}</p></section>")
        return "".join(parts)
    table_of = rao.read(os.path.join(out, "rao.h5"))
    strong_threshold = rao.COHERENCE_THRESHOLD
    rows, idle = [], []
    largest = max((float(np.nanmax(channel.amplitude)) for channel in table_of.channels.values()
                   if np.isfinite(channel.amplitude).any()), default=0.0)
    for name, channel in table_of.channels.items():
        # A mode the sea does not excite (sway, roll and yaw in head seas: ~1e-8 of the
        # others) carries round-off, by the rule of the plots and the joint loads.
        if not np.isfinite(channel.amplitude).any() or np.nanmax(channel.amplitude) <= NOTHING * largest:
            idle.append(name)
            continue
        strong = channel.coherence >= strong_threshold
        peak = int(np.nanargmax(np.where(strong, channel.amplitude, np.nan))) if strong.any() else None
        error = phase_error = None
        if channel.bem_amplitude is not None and strong.any():
            # Judged where the estimate is trustworthy (coherence) and the RAO is at least
            # 10 % of its largest (a phase of almost nothing is noise): docs/rao.md's bar.
            reference = np.abs(channel.bem_amplitude)
            judged = strong & (reference >= 0.1 * np.nanmax(reference[strong]))
            error = float(np.max(np.abs(channel.amplitude[judged] - reference[judged]) / np.max(reference[judged])))
            phase_error = float(np.max(np.abs((channel.phase[judged] - channel.bem_phase[judged] + 180.0) % 360.0
                                              - 180.0)))
        rows.append([text_cell(name), text_cell(channel.unit), cell(int(strong.sum()), 6),
                     cell(channel.amplitude[peak] if peak is not None else None),
                     cell(table_of.period[peak] if peak is not None else None),
                     cell(100.0 * error if error is not None else None, 3),
                     cell(phase_error, 3)])
    parts.append(f"<p>Transfer functions from the recorded wave elevation to each response (H1 = S_xy / S_xx, "
                 f"Welch segments), per unit wave amplitude, phase relative to the wave crest at the platform's "
                 f"reference point; points with coherence below {strong_threshold:g} are faint in the figure and "
                 f"left out of the table, as are, for the comparison with the frequency-domain RAO of the case's BEM data "
                 f"(the line), bins where that RAO is below 10 % of its largest.</p>")
    parts.append(table("rao-table", ["channel", "unit", "bins with coherence ≥ 0.9", "peak |RAO|", "at period [s]",
                                     "largest |ΔRAO| / peak vs BEM [%]", "largest phase difference [deg]"], rows))
    if idle:
        parts.append(f"<p>No response (below 1e-6 of the largest RAO: round-off), not listed or drawn: "
                     f"{html.escape(', '.join(idle))}.</p>")
    figure_path = os.path.join(directory, "rao.png")
    rao.figure(table_of, figure_path, channels=[name for name in table_of.channels if name not in idle])
    parts.append(embed_png(figure_path, "RAOs: H1 from this run and the frequency-domain RAO"))
    parts.append("</section>")
    return "".join(parts)


# The page checks itself once loaded: an image that did not decode is counted, written
# to <body data-failed-images> and announced in a banner, so a reader (and the browser
# test) sees a broken figure instead of a blank space.
CHECK_SCRIPT = """<script>
window.addEventListener("load", function () {
  var images = document.images, failed = 0;
  for (var i = 0; i < images.length; ++i)
    if (!(images[i].complete && images[i].naturalWidth > 0)) ++failed;
  document.body.setAttribute("data-images", String(images.length));
  document.body.setAttribute("data-failed-images", String(failed));
  if (failed > 0) {
    var banner = document.createElement("div");
    banner.id = "broken-images";
    banner.className = "banner";
    banner.textContent = failed + " of " + images.length + " figures of this report could not be shown.";
    document.body.insertBefore(banner, document.body.firstChild);
  }
});
</script>"""

STYLE = """<style>
body { font-family: sans-serif; margin: 1.5em; color: #111; max-width: 1400px; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; border-bottom: 1px solid #999; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 0.82em; }
th, td { border: 1px solid #bbb; padding: 2px 6px; text-align: left; }
td[data-value] { text-align: right; font-variant-numeric: tabular-nums; }
caption { text-align: left; font-style: italic; }
#channel-statistics { font-size: 0.72em; }
.banner { background: #b00020; color: white; padding: 0.8em; font-size: 1.1em; margin: 0.5em 0; }
figure { margin: 0.8em 0; } img { max-width: 100%; } figcaption { font-size: 0.85em; color: #444; }
pre { font-size: 0.75em; background: #f4f4f4; padding: 0.5em; overflow: auto; }
</style>"""


def report(r, binary, duration, start, log_path):
    stats, window_start, message = run_stats(binary, r.path, duration, start)
    if window_start is None:
        window_start = r.attributes.get("statistics_window_start")
    case = case_model(r)
    with tempfile.TemporaryDirectory(prefix="heavesim_report_") as directory:
        sections = [
            failure_banner(r),
            summary_section(r, case, window_start, duration),
            design_section(r, case, stats),
            model_section(r, case),
            validation_section(binary, r, log_path),
            compensator_section(r, case, directory),
            joint_loads_section(r, stats, duration),
            rao_section(binary, r, case, directory),
            figures_section(r, stats, window_start, directory),
            statistics_section(r, stats, message),
        ]
    made = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    title = f"heavesim report: {r.attributes.get('case_name', os.path.basename(r.path))}"
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"{STYLE}</head>\n<body data-complete=\"{int(r.complete)}\">\n<h1>{html.escape(title)}</h1>"
            f"<p>{html.escape(r.path)}, report made {made}.</p>\n" + "\n".join(s for s in sections if s) +
            f"\n{CHECK_SCRIPT}\n</body></html>\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="heavesim result file (HDF5)")
    parser.add_argument("-o", "--output", help="the HTML file (default: <result stem>_report.html beside the result)")
    parser.add_argument("--duration", type=float, default=DEFAULT_DURATION, help="s, D of the most probable maxima")
    parser.add_argument("--from", dest="start", type=float, default=None,
                        help="s, start of the evaluation window (default: the file's own)")
    parser.add_argument("--validation", type=pathlib.Path, help="a saved `heavesim validate` output to include")
    parser.add_argument("--heavesim", default=str(HERE.parent / os.environ.get("HEAVESIM_BUILD_DIR", "build") / "heavesim"),
                        help="the heavesim executable (stats, version, validation list)")
    args = parser.parse_args()
    output = args.output or os.path.splitext(args.result)[0] + "_report.html"
    try:
        if not (args.duration > 0.0 and math.isfinite(args.duration)):
            raise BadInput("--duration", "", f"{args.duration}", "a duration > 0 s (default 10800 s = 3 h)")
        if args.start is not None and not math.isfinite(args.start):
            raise BadInput("--from", "", f"{args.start}", "a finite time in s")
        if args.validation is not None and not args.validation.is_file():
            raise BadInput(str(args.validation), "", "no such file", "the saved output of `heavesim validate`")
        r = open_result(args.result)
    except BadInput as error:
        print(f"heavesim: bad input: {error}", file=sys.stderr)
        return 2
    with r:
        page = report(r, args.heavesim, args.duration, args.start, args.validation)
    with open(output, "w", encoding="utf-8") as out:
        out.write(page)
    print(f"report: wrote {output} ({len(page) / 1e6:.2f} MB)" + ("" if r.complete else " (an INCOMPLETE result)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
