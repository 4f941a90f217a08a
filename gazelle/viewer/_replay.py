"""A replay of a run as one self-contained HTML file: opens from disk, no server, no gazelle, no network.

The page draws the world from above (every body's collision shapes as their outlines on the ground plane,
the higher drawn over the lower), the paths of the bodies that moved (the whole path faint, the part up to
the cursor over it), each lidar's rays at the cursor, a timeline to play, pause and scrub (it opens at the
end of the run), and the recorded topics' values at the cursor (quaternions as ROS writes them: x, y, z, w). The data is :meth:`gazelle.sim.ReplayRecorder.data` (with its topic
samples ``{topic: [[sim_time, {field: value}], ...]}``, or others given), inlined as JSON; the drawing is
a few hundred lines of plain JavaScript on a canvas (no library), so the file is its data plus ~10 KB.

``window.gazelleReplay`` lets a test drive the page: ``frames``, ``times``, ``seek(i)``, ``toScreen(x, y)``
(canvas pixels of a world point), ``colorOf(entity)`` and ``raysAt(i)`` (each lidar's origin and hits at frame ``i``).
"""

from __future__ import annotations

import html
import json
import re
from typing import Any

PALETTE = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42d4f4", "#f032e6", "#bfef45", "#9a6324"]
"""Colours of the bodies, in the order they are met (the first is red; a ground plane stays pale)."""

_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><meta name="generator" content="gazelle replay"><title>__TITLE__</title>
<style>
body { font: 13px system-ui, sans-serif; margin: 0; background: #f4f4f4; color: #222; display: flex; }
#main { padding: 10px; }
#side { padding: 10px; width: 360px; max-height: 100vh; overflow: auto; }
canvas { background: #fff; border: 1px solid #ccc; display: block; }
#bar { display: flex; gap: 8px; align-items: center; margin-top: 6px; }
#cursor { flex: 1; }
pre { white-space: pre-wrap; margin: 2px 0 10px; font-size: 12px; }
h1 { font-size: 15px; margin: 0 0 6px; } h2 { font-size: 13px; margin: 8px 0 2px; }
.key span { display: inline-block; width: 10px; height: 10px; margin-right: 4px; }
</style></head>
<body><div id="main"><h1>__TITLE__</h1>
<canvas id="view" width="900" height="640"></canvas>
<div id="bar"><button id="play">play</button><input id="cursor" type="range" min="0" value="0">
<select id="speed"><option>0.25</option><option>0.5</option><option selected>1</option><option>2</option>
<option>4</option><option>10</option></select><span id="time"></span></div>
<div id="key" class="key"></div></div>
<div id="side"><h1>Topics at the cursor</h1><div id="topics">none recorded</div></div>
<script id="data" type="application/json">__DATA__</script>
<script>
"use strict";
const D = JSON.parse(document.getElementById("data").textContent);
const PALETTE = __PALETTE__;
const frames = D.frames, shapes = D.shapes, topics = D.topics || {};
const canvas = document.getElementById("view"), ctx = canvas.getContext("2d");
const slider = document.getElementById("cursor");
slider.max = Math.max(0, frames.length - 1);
const entityOf = (link) => link.split("::")[0];
function rot(q, v) {  // q = [w, x, y, z]
  const [w, x, y, z] = q, [a, b, c] = v;
  const tx = 2 * (y * c - z * b), ty = 2 * (z * a - x * c), tz = 2 * (x * b - y * a);
  return [a + w * tx + (y * tz - z * ty), b + w * ty + (z * tx - x * tz), c + w * tz + (x * ty - y * tx)];
}
function compose(p, s) {  // poses as [x, y, z, qw, qx, qy, qz]
  const t = rot(p.slice(3), s.slice(0, 3));
  const [w1, x1, y1, z1] = p.slice(3), [w2, x2, y2, z2] = s.slice(3);
  return [p[0] + t[0], p[1] + t[1], p[2] + t[2],
    w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
    w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2];
}
function points(shape) {  // the shape's outline points in its own frame
  const s = shape.size, out = [];
  if (shape.kind === "box") {
    for (const i of [-0.5, 0.5]) for (const j of [-0.5, 0.5]) for (const k of [-0.5, 0.5]) out.push([i * s[0], j * s[1], k * s[2]]);
  } else {
    const r = shape.kind === "sphere" ? s[0] : s[1], h = shape.kind === "sphere" ? 0 : s[0] / 2;
    for (let n = 0; n < 16; n++) {
      const a = 2 * Math.PI * n / 16, x = r * Math.cos(a), y = r * Math.sin(a);
      if (shape.kind === "sphere") { out.push([x, y, 0], [x, 0, y], [0, x, y]); } else { out.push([x, y, -h], [x, y, h]); }
    }
  }
  return out;
}
function hull(pts) {  // 2-D convex hull, monotone chain
  pts = pts.slice().sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lo = [], up = [];
  for (const p of pts) { while (lo.length >= 2 && cross(lo[lo.length - 2], lo[lo.length - 1], p) <= 0) lo.pop(); lo.push(p); }
  for (const p of pts.slice().reverse()) { while (up.length >= 2 && cross(up[up.length - 2], up[up.length - 1], p) <= 0) up.pop(); up.push(p); }
  return lo.slice(0, -1).concat(up.slice(0, -1));
}
const local = {};
for (const [link, list] of Object.entries(shapes)) local[link] = list.map((s) => ({ pose: s.pose, pts: points(s) }));
function outlines(frame) {  // [{entity, z, poly}] of one frame, lowest first
  const out = [];
  for (const [link, pose] of Object.entries(frame)) {
    for (const s of local[link] || []) {
      const w = compose(pose, s.pose);
      const pts = s.pts.map((p) => { const r = rot(w.slice(3), p); return [w[0] + r[0], w[1] + r[1], w[2] + r[2]]; });
      out.push({ entity: entityOf(link), z: Math.max(...pts.map((p) => p[2])), poly: hull(pts.map((p) => [p[0], p[1]])),
                 extent: Math.max(...pts.map((p) => Math.abs(p[0] - w[0]) + Math.abs(p[1] - w[1]))) });
    }
  }
  return out.sort((a, b) => a.z - b.z);
}
// bodies that move get colours; their first link's track is their path
const first = frames.length ? frames[0][1] : {}, last = frames.length ? frames[frames.length - 1][1] : {};
const moving = [], track = {};
for (const link of Object.keys(first)) {
  const e = entityOf(link), a = first[link], b = last[link];
  if (b && Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) > 0.01 && !moving.includes(e)) moving.push(e);
}
for (const [t, frame] of frames) for (const [link, p] of Object.entries(frame)) {
  const e = entityOf(link);
  if (moving.includes(e) && !(e in track && track[e].link !== link)) { (track[e] = track[e] || { link, xy: [] }).xy.push([p[0], p[1]]); }
}
// every body gets a colour, in the order met (a ground plane of 100 m is left pale)
const bodies = [];
for (const f of frames) for (const o of outlines(f[1])) if (o.extent < 30 && !bodies.includes(o.entity)) bodies.push(o.entity);
const colorOf = (e) => bodies.includes(e) ? PALETTE[bodies.indexOf(e) % PALETTE.length] : "#b8b8b8";
// the view: what moved and what is near it (a ground plane of 100 m is left out of the fit)
let box = [Infinity, Infinity, -Infinity, -Infinity];
const grow = (x, y) => { box = [Math.min(box[0], x), Math.min(box[1], y), Math.max(box[2], x), Math.max(box[3], y)]; };
for (const f of [0, frames.length - 1]) if (frames[f]) for (const o of outlines(frames[f][1])) if (o.extent < 30) for (const p of o.poly) grow(p[0], p[1]);
for (const e of Object.values(track)) for (const p of e.xy) grow(p[0], p[1]);
if (!isFinite(box[0])) box = [-1, -1, 1, 1];
const pad = 0.08 * Math.max(box[2] - box[0], box[3] - box[1], 0.5);
box = [box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad];
const scale = Math.min(canvas.width / (box[2] - box[0]), canvas.height / (box[3] - box[1]));
const toScreen = (x, y) => [(x - box[0]) * scale + (canvas.width - (box[2] - box[0]) * scale) / 2,
                            canvas.height - ((y - box[1]) * scale + (canvas.height - (box[3] - box[1]) * scale) / 2)];
function draw(i) {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (!frames.length) return;
  const [t, frame] = frames[i];
  ctx.lineWidth = 1;
  for (const o of outlines(frame)) {
    ctx.beginPath();
    o.poly.forEach((p, k) => { const [x, y] = toScreen(p[0], p[1]); k ? ctx.lineTo(x, y) : ctx.moveTo(x, y); });
    ctx.closePath();
    ctx.fillStyle = o.extent >= 30 ? "#eef3ea" : colorOf(o.entity);
    ctx.fill();
    ctx.strokeStyle = "#555"; ctx.stroke();
  }
  for (const [e, tr] of Object.entries(track)) {  // the whole path, faint, and the path so far over it
    for (const [n, width, alpha] of [[tr.xy.length, 1, 0.25], [Math.min(tr.xy.length, i + 1), 2, 0.7]]) {
      ctx.beginPath();
      for (let k = 0; k < n; k++) { const [x, y] = toScreen(tr.xy[k][0], tr.xy[k][1]); k ? ctx.lineTo(x, y) : ctx.moveTo(x, y); }
      ctx.lineWidth = width; ctx.strokeStyle = colorOf(e); ctx.globalAlpha = alpha; ctx.stroke();
    }
    ctx.globalAlpha = 1;
  }
  for (const [sensor, r] of Object.entries(frames[i][2] || {})) {  // each lidar's rays at the cursor
    const [ox, oy] = toScreen(r[0], r[1]);
    ctx.strokeStyle = colorOf(entityOf(sensor)); ctx.fillStyle = ctx.strokeStyle; ctx.lineWidth = 1;
    ctx.globalAlpha = 0.3; ctx.beginPath();
    for (let k = 2; k + 1 < r.length; k += 2) { const [x, y] = toScreen(r[k], r[k + 1]); ctx.moveTo(ox, oy); ctx.lineTo(x, y); }
    ctx.stroke(); ctx.globalAlpha = 1;
    for (let k = 2; k + 1 < r.length; k += 2) { const [x, y] = toScreen(r[k], r[k + 1]); ctx.fillRect(x - 2, y - 2, 4, 4); }
  }
  // a scale bar, bottom left
  const len = [0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100].filter((l) => l * scale <= canvas.width / 4).pop() || 0.05;
  ctx.strokeStyle = "#333"; ctx.fillStyle = "#333"; ctx.lineWidth = 2;
  ctx.beginPath(); ctx.moveTo(12, canvas.height - 14); ctx.lineTo(12 + len * scale, canvas.height - 14); ctx.stroke();
  ctx.fillText(`${len} m`, 12, canvas.height - 20);
  document.getElementById("time").textContent = `t = ${t.toFixed(2)} s of ${frames[frames.length - 1][0].toFixed(2)} s`;
  const shown = [];
  for (const [name, samples] of Object.entries(topics)) {
    let k = -1;
    while (k + 1 < samples.length && samples[k + 1][0] <= t) k++;
    const text = k < 0 ? "(nothing yet)" : Object.entries(samples[k][1]).map(([f, v]) => `${f}: ${v}`).join("\\n");
    const esc = (x) => x.replace(/&/g, "&amp;").replace(/</g, "&lt;");
    shown.push(`<h2>${esc(name)}</h2><pre>${esc(text)}</pre>`);
  }
  if (shown.length) document.getElementById("topics").innerHTML = shown.join("");
}
const escHtml = (x) => x.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
document.getElementById("key").innerHTML = bodies.map((e) => `<span style="background:${colorOf(e)}"></span>${escHtml(e)}`).join(" &nbsp; ");
let playing = false, clock = 0, wall = 0;
function seek(i) { slider.value = String(i); draw(i); }
slider.addEventListener("input", () => draw(Number(slider.value)));
document.getElementById("play").addEventListener("click", () => {
  playing = !playing;
  document.getElementById("play").textContent = playing ? "pause" : "play";
  if (Number(slider.value) >= frames.length - 1) seek(0);
  clock = frames.length ? frames[Number(slider.value)][0] : 0; wall = performance.now();
  if (playing) requestAnimationFrame(tick);
});
function tick(now) {
  if (!playing) return;
  clock += (now - wall) / 1000 * Number(document.getElementById("speed").value); wall = now;
  let i = Number(slider.value);
  while (i + 1 < frames.length && frames[i + 1][0] <= clock) i++;
  seek(i);
  if (i >= frames.length - 1) { playing = false; document.getElementById("play").textContent = "play"; return; }
  requestAnimationFrame(tick);
}
seek(Math.max(0, frames.length - 1));  // opens at the end: where the run stopped, its whole path drawn
const raysAt = (i) => frames[i] ? frames[i][2] || {} : {};
window.gazelleReplay = { frames: frames.length, times: frames.map((f) => f[0]), seek, toScreen, colorOf, moving, bodies, raysAt };
</script></body></html>
"""


def replay_html(data: dict[str, Any], topics: dict[str, list[Any]] | None = None, title: str = "gazelle replay") -> str:
    """The self-contained page of a replay (see the module docstring)."""
    payload = {
        "shapes": data.get("shapes", {}),
        "frames": data.get("frames", []),
        "topics": topics if topics is not None else data.get("topics", {}),
    }
    parts = {"TITLE": html.escape(title), "PALETTE": script_json(PALETTE), "DATA": script_json(payload)}
    return re.sub(r"__(TITLE|PALETTE|DATA)__", lambda m: parts[m.group(1)], _PAGE)  # one pass: data stays data


_SCRIPT_ESCAPES = {ord("<"): "\\u003C", ord(">"): "\\u003E", ord("&"): "\\u0026"}


def script_json(value: Any) -> str:
    """``value`` as JSON that can sit inside an HTML ``<script>`` element, whatever its strings hold: every
    ``<``, ``>`` and ``&`` written as ``\\u003C``, ``\\u003E``, ``\\u0026`` (as Django's ``json_script``
    does), which JSON and JavaScript read back as the same characters.

    Escaping only ``</`` is not enough: the HTML parser also reads ``<!--`` followed by ``<script`` inside a
    script as the start of an escaped section, in which the element's own ``</script>`` no longer ends it,
    so an entity named ``bot<!--<script>`` swallowed the page's code and left it blank. Non-ASCII characters
    (U+2028 and U+2029 among them) are escaped by ``json.dumps`` already. Every JSON a page of gazelle's
    embeds goes through here."""
    return json.dumps(value, separators=(",", ":")).translate(_SCRIPT_ESCAPES)
