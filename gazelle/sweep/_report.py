"""The sweep's report: one self-contained HTML page (plotly's script inlined once) that a person reads
in a browser with no server: the pass rate per parameter value, each metric against each parameter, and
the runs that failed, with their errors."""

from __future__ import annotations

import html
import math
from collections import defaultdict
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from .._files import atomic_write


def _numeric(v: Any) -> bool:
    """Whether ``v`` can be plotted as a number: a finite int or float, not a bool (Python's ``True`` is an
    int, and a metric that says pass/fail is not a value to draw on an axis)."""
    return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(float(v))


def _figures(rows: Sequence[Mapping[str, Any]]) -> list[str]:
    """The report's charts as HTML fragments: a bar chart of the pass rate per value of each parameter, then a
    scatter per (numeric metric, parameter) coloured by status with the seed on hover. Plotly's script goes
    into the first fragment only; the others use it."""
    import plotly.graph_objects as go
    import plotly.io as pio

    params = sorted({k[6:] for r in rows for k in r if k.startswith("param.")})
    metrics = sorted({k[7:] for r in rows for k in r if k.startswith("metric.") and k != "metric.passed"})
    metrics = [m for m in metrics if any(_numeric(r.get(f"metric.{m}")) for r in rows)]
    figures: list[str] = []
    first = True

    def add(fig: Any) -> None:
        nonlocal first
        fig.update_layout(height=360, margin={"l": 60, "r": 20, "t": 50, "b": 50}, template="plotly_white")
        figures.append(pio.to_html(fig, include_plotlyjs=first, full_html=False))
        first = False

    for p in params:
        by_value: dict[Any, list[bool]] = defaultdict(list)
        for r in rows:
            by_value[r.get(f"param.{p}")].append(r["status"] == "passed")
        values = sorted(by_value, key=lambda v: (not _numeric(v), v if _numeric(v) else str(v)))
        rates = [sum(by_value[v]) / len(by_value[v]) for v in values]
        labels = [f"{v:g}" if isinstance(v, float) else str(v) for v in values]
        fig = go.Figure(go.Bar(x=labels, y=rates, text=[f"{x:.0%}" for x in rates], marker_color="#3b7dd8"))
        fig.update_layout(title=f"pass rate by {p}", xaxis_title=p, yaxis={"title": "pass rate", "range": [0, 1.05]})
        add(fig)
    for m in metrics:
        for p in params:
            fig = go.Figure()
            for status, color in (("passed", "#2a9d5c"), ("failed", "#d1495b"), ("error", "#888888")):
                pts = [r for r in rows if r["status"] == status and _numeric(r.get(f"metric.{m}"))]
                if pts:
                    fig.add_trace(
                        go.Scatter(
                            x=[r.get(f"param.{p}") for r in pts],
                            y=[r[f"metric.{m}"] for r in pts],
                            mode="markers",
                            name=status,
                            marker={"color": color, "size": 7, "opacity": 0.75},
                            text=[f"seed {r['seed']}" for r in pts],
                        )
                    )
            fig.update_layout(title=f"{m} against {p}", xaxis_title=p, yaxis_title=m)
            add(fig)
    return figures


def write_report(rows: Sequence[Mapping[str, Any]], path: Path, title: str = "sweep") -> None:
    """Write the report of ``rows`` (the results table's rows: ``status``, ``seed``, ``param.*``, ``metric.*``,
    ``artifact.*``, ``error``, ``wall_sec``) to ``path``.

    The page has, in order: a one-line summary (``#summary``), one bar chart of the pass rate per value of
    each parameter, one scatter per (numeric metric, parameter) coloured by status with the seed on hover, and
    a table of the runs that did not pass (``#failures``), each with its parameters, links to its artifacts
    (its replay) and the last line of its error. Plotly's script goes into the first figure only and every
    other figure reuses it, so the page opens from disk with no network and stays a few MB however many
    figures it has. At most 500 failing runs are listed: past that the charts say more than the rows.
    Every value that came from a run is HTML-escaped."""
    passed = sum(r["status"] == "passed" for r in rows)
    figures = _figures(rows)
    failing = [r for r in rows if r["status"] != "passed"]
    failing_rows = "\n".join(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td><pre>{}</pre></td></tr>".format(
            html.escape(r["status"]),
            r["seed"],
            html.escape(", ".join(f"{k[6:]}={r[k]}" for k in sorted(r) if k.startswith("param."))),
            "".join(
                f'<a href="{html.escape(str(r[k]))}">{html.escape(k[9:])}</a> '
                for k in sorted(r)
                if k.startswith("artifact.")
            ),
            html.escape((r.get("error") or "").strip().splitlines()[-1] if r.get("error") else ""),
        )
        for r in failing[:500]
    )
    wall = sum(float(r.get("wall_sec", 0.0)) for r in rows)
    page = f"""<!doctype html>
<html><head><meta charset="utf-8"><title>{html.escape(title)}: sweep report</title>
<style>body{{font-family:system-ui,sans-serif;margin:24px;color:#222}} table{{border-collapse:collapse}}
td,th{{border:1px solid #ccc;padding:4px 8px;text-align:left;vertical-align:top}} pre{{margin:0;white-space:pre-wrap}}
.summary{{font-size:1.2em}}</style></head><body>
<h1>{html.escape(title)}</h1>
<p class="summary" id="summary">{len(rows)} runs: <b>{passed} passed</b>, {len(rows) - passed} failed or raised
(pass rate {passed / len(rows) if rows else 0:.1%}); {wall:.1f} s of run time in all.</p>
{"".join(f'<div class="plot">{f}</div>' for f in figures)}
<h2 id="failures">Runs that did not pass ({len(failing)})</h2>
<table><tr><th>status</th><th>seed</th><th>parameters</th><th>artifacts</th><th>error</th></tr>
{failing_rows}
</table></body></html>
"""
    atomic_write(path, page)
