#include "viewer/viewer_page.h"

namespace pathspace::viewer {

// The page asks for one frame at a time ({"cmd":"frame"}), so a slow client receives fewer frames
// and never holds the renderer back; camera keys follow pbrt-v4's --interactive (docs/viewer.md).
const char* const kViewerPage = R"PAGE(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pathspace view</title>
<style>
body { margin: 0; background: #202124; color: #e8eaed; font: 14px sans-serif; }
#bar { padding: 6px 10px; display: flex; gap: 14px; align-items: center; flex-wrap: wrap; }
#frame { display: block; margin: 0 10px; image-rendering: pixelated; outline: none; }
#error { color: #f28b82; }
/* One line whatever it says: a status that wrapped as its numbers changed would move the image. */
#status { display: block; padding: 6px 10px 0; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
#cli { width: 40em; }
#main { display: flex; gap: 16px; align-items: flex-start; }
#options { font-size: 12px; max-height: 90vh; overflow-y: auto; }
#options td { padding: 1px 4px; }
#options input[type=text] { width: 7em; }
#details { font: 11px monospace; white-space: pre; color: #bdc1c6; }
</style></head>
<body>
<div id="status">connecting</div>
<div id="bar">
  <label>exposure <input id="exposure" type="range" min="-8" max="8" step="0.5" value="0"></label>
  <label>tone <select id="tonemap"><option value="clip">clip</option><option value="reinhard">reinhard</option><option value="aces">aces</option></select></label>
  <label>show <select id="show"><option value="image">image</option></select></label>
  <label>right half: <select id="split"><option value="off">off</option></select></label>
  <span>speed <span id="speed">1</span>x (+/-)</span>
  <button id="save">Save</button>
  <button id="record">Record</button>
  <span id="animation" hidden><button id="play">Play</button>
    <label>time <input id="time" type="number" min="0" step="0.1" style="width: 5em"> s</label></span>
  <button id="copy">CLI options</button>
  <input id="cli" readonly>
  <span id="saved"></span>
  <span id="error"></span>
</div>
<div id="main">
  <div><img id="frame" tabindex="0" alt="render">
  <p style="margin: 6px 10px">W/A/S/D/Q/E move, arrow keys or drag turn, R resets the view, a click inspects a pixel.</p>
  <div id="pixel" style="margin: 6px 10px"></div>
  <div id="metrics"></div>
  <canvas id="plot" width="360" height="140" hidden></canvas>
  <div id="details"></div></div>
  <div id="options"></div>
</div>
<script>
"use strict";
const params = new URLSearchParams(location.search);
const token = params.get("token");
const ws = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/ws" + (token ? "?token=" + encodeURIComponent(token) : ""));
ws.binaryType = "blob";
const img = document.getElementById("frame"), status = document.getElementById("status"), error = document.getElementById("error");
let speed = 1, frames = 0, lastUrl = null, stats = null, keptError = null, lastErrorId = null;
const send = o => { if (ws.readyState === WebSocket.OPEN) ws.send(JSON.stringify(o)); };
ws.onopen = () => { status.textContent = "connected"; send({cmd: "options"}); send({cmd: "frame"}); };
// The integrator's and filter's options from the registry: each change is sent as the command line
// would give it; the server answers with the options now in force, or with the CLI's error.
const select = (name, values, current) => {
  const s = document.createElement("select");
  s.id = "opt-" + name;
  for (const v of values) { const o = document.createElement("option"); o.value = o.textContent = v; s.appendChild(o); }
  s.value = current;
  s.addEventListener("change", () => send({cmd: "set", name, value: s.value}));
  return s;
};
const showOptions = m => {
  const panel = document.getElementById("options");
  panel.textContent = "";
  const head = document.createElement("div");
  head.append("integrator ", select("integrator", m.integrators, m.integrator), " filter ", select("filter", m.filters, m.filter),
              " device ", select("device", m.devices, m.device));
  panel.appendChild(head);
  const table = document.createElement("table");
  for (const o of m.list) {
    const row = table.insertRow(), label = row.insertCell(), cell = row.insertCell();
    label.textContent = "--" + o.name;
    label.title = o.help + (o.paper ? " (" + o.paper + ")" : "");
    let input;
    if (o.type === "flag") {
      input = document.createElement("input");
      input.type = "checkbox";
      input.checked = o.value !== null;
      input.addEventListener("change", () => send(input.checked ? {cmd: "set", name: o.name, value: ""} : {cmd: "unset", name: o.name}));
    } else if (o.choices) {
      input = select(o.name, o.choices, o.value !== null ? o.value : o.default);
    } else {
      input = document.createElement("input");
      input.type = "text";
      input.value = o.value !== null ? o.value : "";
      input.placeholder = o.default;
      input.title = o.min !== undefined ? `${o.min} to ${o.max}` : "";
      input.addEventListener("change", () => send(input.value === "" ? {cmd: "unset", name: o.name} : {cmd: "set", name: o.name, value: input.value}));
    }
    input.id = "opt-" + o.name;
    cell.appendChild(input);
  }
  panel.appendChild(table);
};
ws.onclose = () => { status.textContent = "disconnected"; };
ws.onmessage = e => {
  if (typeof e.data === "string") {
    const m = JSON.parse(e.data);
    if (m.error) error.textContent = m.error;
    if (m.options) {
      error.textContent = keptError || "";  // a new choice clears the last error, the options restored after one keep it
      keptError = null;
      showOptions(m.options);
      const split = document.getElementById("split");
      if (split.options.length === 1) {
        for (const f of m.options.filters) { const o = document.createElement("option"); o.value = "filter:" + f; o.textContent = "filter " + f; split.appendChild(o); }
        for (const i of m.options.integrators) { const o = document.createElement("option"); o.value = "integrator:" + i; o.textContent = "integrator " + i; split.appendChild(o); }
      }
    }
    if (m.pixel) {
      const p = m.pixel, f = v => v.map(c => c.toPrecision(4)).join(" ");
      let t = `pixel (${p.x}, ${p.y})${p.half ? " " + p.half + " half" : ""}: ${f(p.mean)} ± ${f(p.std_error)}, luminance ${p.luminance.toPrecision(4)}, ${p.samples} paths`;
      if (p.reference) t += `; reference ${f(p.reference)}, luminance error ${(100 * p.rel_error).toFixed(1)}%`;
      document.getElementById("pixel").textContent = t;
    }
    if (m.saved) { error.textContent = ""; document.getElementById("saved").textContent = "saved " + m.saved.join(", "); }
    if (m.recording) { recording = true; document.getElementById("record").textContent = "Stop"; document.getElementById("saved").textContent = "recording " + m.recording; }
    if (m.recorded !== undefined) {
      recording = false;
      document.getElementById("record").textContent = "Record";
      document.getElementById("saved").textContent = `recorded ${m.recorded} frames (${m.frames})` + (m.video ? ", video " + m.video : "");
    }
    if (m.stats) {
      stats = m.stats;
      if (stats.error && stats.error.id !== lastErrorId) {  // the render went back to the options before
        lastErrorId = stats.error.id;
        error.textContent = keptError = stats.error.message;
        send({cmd: "options"});
      }
      status.textContent = `${stats.width}x${stats.height}, ${stats.spp} spp, view ${stats.view}, ${stats.passes_per_second.toFixed(1)} passes/s`;
      if (stats.preview > 1) status.textContent += `, preview at 1/${stats.preview}`;
      document.getElementById("cli").value = stats.camera_options;
      const show = document.getElementById("show");
      if (Array.from(show.options).map(o => o.value).join() !== stats.images.join()) {
        show.textContent = "";
        for (const n of stats.images) { const o = document.createElement("option"); o.value = o.textContent = n; show.appendChild(o); }
      }
      show.value = stats.shown;
      status.textContent += `, ${stats.integrator}${stats.filter && stats.filter !== "none" ? " + " + stats.filter : ""}`;
      if (stats.split) status.textContent += ` | right half: ${stats.split}`;
      if (stats.animation) {
        document.getElementById("animation").hidden = false;
        document.getElementById("play").textContent = stats.animation.playing ? "Pause" : "Play";
        const time = document.getElementById("time");
        if (document.activeElement !== time) time.value = stats.animation.seconds.toFixed(2);
        status.textContent += `, t ${stats.animation.seconds.toFixed(2)} s`;
      }
      if (stats.metrics) plotMetrics(stats.view, stats.metrics);
      document.getElementById("details").textContent = Object.entries(stats.details).map(([k, v]) => k + " " + JSON.stringify(v)).join("\n");
    }
    return;
  }
  const url = URL.createObjectURL(e.data);
  img.onload = () => {
    if (lastUrl) URL.revokeObjectURL(lastUrl);
    lastUrl = url;
    // Small renders are shown enlarged by a whole factor (sharp pixels), up to 512 wide.
    img.style.width = img.naturalWidth * Math.max(1, Math.floor(512 / img.naturalWidth)) + "px";
    img.dataset.frames = String(++frames);  // frames shown (decoded), for the tests and the benchmark
  };
  img.src = url;
  send({cmd: "frame"});
};
// --reference: the metrics of each frame, and relMSE and block relMSE of the current view against
// its seconds on a log scale.
let series = {view: -1, points: []};
const plotMetrics = (view, m) => {
  document.getElementById("metrics").textContent =
    `relMSE ${m.rel_mse.toPrecision(3)}, block relMSE ${m.block_rel_mse.toPrecision(3)}, blotched ${(100 * m.blotched_share).toFixed(2)}%, FLIP ${m.flip.toFixed(4)} at ${m.spp} spp, ${m.seconds.toFixed(1)} s`;
  if (series.view !== view) series = {view, points: []};
  series.points.push([m.seconds, m.rel_mse, m.block_rel_mse]);
  const c = document.getElementById("plot"), g = c.getContext("2d");
  c.hidden = false;
  g.fillStyle = "#202124"; g.fillRect(0, 0, c.width, c.height);
  const pts = series.points, tmax = Math.max(...pts.map(p => p[0]), 1e-3);
  const logs = pts.flatMap(p => [p[1], p[2]]).filter(v => v > 0).map(Math.log10);
  const lo = Math.floor(Math.min(...logs)), hi = Math.ceil(Math.max(...logs)) + (logs.length ? 0 : 1);
  const x = t => 30 + (c.width - 40) * t / tmax, y = v => 10 + (c.height - 30) * (hi - Math.log10(v)) / Math.max(hi - lo, 1);
  g.fillStyle = "#9aa0a6"; g.font = "10px sans-serif";
  g.fillText("1e" + hi, 0, 14); g.fillText("1e" + lo, 0, c.height - 20); g.fillText(tmax.toFixed(1) + " s", c.width - 40, c.height - 4);
  for (const [k, colour] of [[1, "#8ab4f8"], [2, "#f28b82"]]) {
    g.strokeStyle = colour; g.beginPath();
    pts.forEach((p, i) => { if (p[k] > 0) (i ? g.lineTo : g.moveTo).call(g, x(p[0]), y(p[k])); });
    g.stroke();
  }
  g.fillStyle = "#8ab4f8"; g.fillText("relMSE", 40, c.height - 4);
  g.fillStyle = "#f28b82"; g.fillText("block relMSE", 90, c.height - 4);
};
const keys = {w: [0, 0, 1], s: [0, 0, -1], a: [-1, 0, 0], d: [1, 0, 0], q: [0, -1, 0], e: [0, 1, 0]};
document.addEventListener("keydown", ev => {
  if (ev.target.tagName === "INPUT" || ev.target.tagName === "SELECT") return;  // typing a value moves nothing
  const k = ev.key.toLowerCase();
  if (keys[k]) { const [r, u, f] = keys[k]; send({cmd: "move", right: r * speed, up: u * speed, forward: f * speed}); }
  else if (ev.key === "ArrowLeft") send({cmd: "turn", yaw: 5});
  else if (ev.key === "ArrowRight") send({cmd: "turn", yaw: -5});
  else if (ev.key === "ArrowUp") send({cmd: "turn", pitch: 5});
  else if (ev.key === "ArrowDown") send({cmd: "turn", pitch: -5});
  else if (k === "r") send({cmd: "reset"});
  else if (ev.key === "+" || ev.key === "=") speed *= 2;
  else if (ev.key === "-") speed /= 2;
  else return;
  document.getElementById("speed").textContent = String(speed);
  ev.preventDefault();
});
// A drag turns the camera; a click without a drag inspects the pixel under the pointer.
let drag = null, dragged = false;
img.addEventListener("mousedown", ev => { drag = [ev.clientX, ev.clientY]; dragged = false; ev.preventDefault(); });
document.addEventListener("mouseup", ev => {
  // The render's size from the statistics: while the next frame decodes, the img has none.
  const r = img.getBoundingClientRect(), x = ev.clientX - r.left, y = ev.clientY - r.top;
  if (drag && !dragged && stats && x >= 0 && y >= 0 && x < r.width && y < r.height)
    send({cmd: "inspect", x: Math.min(stats.width - 1, Math.floor(x * stats.width / r.width)),
          y: Math.min(stats.height - 1, Math.floor(y * stats.height / r.height))});
  drag = null;
});
document.addEventListener("mousemove", ev => {
  if (!drag) return;
  const dx = ev.clientX - drag[0], dy = ev.clientY - drag[1];
  if (Math.abs(dx) + Math.abs(dy) < 4) return;
  drag = [ev.clientX, ev.clientY];
  dragged = true;
  send({cmd: "turn", yaw: -dx * 0.2, pitch: -dy * 0.2});
});
document.getElementById("split").addEventListener("change", ev => {
  const [kind, name] = ev.target.value.split(":");
  send(kind === "integrator" ? {cmd: "split", integrator: name, filter: "none"} : {cmd: "split", filter: name || "off"});
});
document.getElementById("play").addEventListener("click", () => send({cmd: "play", on: !(stats && stats.animation && stats.animation.playing)}));
document.getElementById("time").addEventListener("change", ev => send({cmd: "seek", seconds: Math.max(0, Number(ev.target.value) || 0)}));
let recording = false;
document.getElementById("record").addEventListener("click", () => send({cmd: "record", on: !recording}));
document.getElementById("save").addEventListener("click", () => send({cmd: "save"}));
document.getElementById("show").addEventListener("change", ev => send({cmd: "show", image: ev.target.value}));
document.getElementById("exposure").addEventListener("input", ev => send({cmd: "exposure", stops: Number(ev.target.value)}));
document.getElementById("tonemap").addEventListener("change", ev => send({cmd: "tonemap", name: ev.target.value}));
document.getElementById("copy").addEventListener("click", () => {
  const cli = document.getElementById("cli");
  cli.select();
  if (navigator.clipboard) navigator.clipboard.writeText(cli.value).catch(() => {});
});
</script>
</body></html>
)PAGE";

}  // namespace pathspace::viewer
