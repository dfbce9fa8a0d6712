// moire monitor page: the state arrives on the websocket /api/live (the JSON of GET /api/state, docs/monitor.md);
// the socket reconnects every second when it closes. No libraries, no network beyond this server.
"use strict";
const $ = id => document.getElementById(id);
let state = null;

function fmt(v, d) { return v === null || v === undefined || !isFinite(v) ? "-" : Number(v).toFixed(d); }

function drawLissajous(s) {
  const c = $("lissajous"), g = c.getContext("2d"), w = c.width, h = c.height;
  g.clearRect(0, 0, w, h);
  const sc = w / 2 / 1.05, X = x => w / 2 + x * sc, Y = y => h / 2 - y * sc;
  g.strokeStyle = "#ddd"; g.lineWidth = 1;
  g.beginPath(); g.moveTo(0, h / 2); g.lineTo(w, h / 2); g.moveTo(w / 2, 0); g.lineTo(w / 2, h); g.stroke();
  g.strokeRect(X(-1), Y(1), 2 * sc, 2 * sc);
  let n = 0;
  if (s.points) {
    g.fillStyle = "#1565c0";
    const xs = s.points.cos, ys = s.points.sin;
    for (let i = 0; i < xs.length; i++) { if (xs[i] === null || ys[i] === null) continue; g.fillRect(X(xs[i]) - 1, Y(ys[i]) - 1, 2, 2); n++; }
  }
  const e = s.ellipse;
  if (e) {
    g.strokeStyle = "#9e9e9e"; g.lineWidth = 1.5; g.setLineDash([5, 4]);
    g.beginPath(); g.arc(w / 2, h / 2, e.ideal_radius * sc, 0, 2 * Math.PI); g.stroke(); g.setLineDash([]);
    g.strokeStyle = "#e65100"; g.lineWidth = 2; g.beginPath();
    e.outline.forEach((p, i) => i ? g.lineTo(X(p[0]), Y(p[1])) : g.moveTo(X(p[0]), Y(p[1]))); g.stroke();
  }
  c.dataset.points = n;
  c.dataset.ellipse = e ? "yes" : "no";
}

function gauge(r) {
  const lo = r.lo - (r.hi - r.lo) * 0.5, hi = r.hi + (r.hi - r.lo) * 0.5, p = v => Math.max(0, Math.min(100, (v - lo) / (hi - lo) * 100));
  return `<div class="gauge"><div class="ok" style="left:${p(r.lo)}%;width:${p(r.hi) - p(r.lo)}%"></div>` +
    `<div class="mark" style="left:${p(r.lo)}%"></div><div class="mark" style="left:${p(r.hi)}%"></div>` +
    `<div class="val" style="left:calc(${p(r.value)}% - 2px)"></div></div>`;
}

function readouts(s) {
  const body = $("readouts").tBodies[0];
  if (!s.readouts) { body.innerHTML = "<tr><td>no ellipse yet (fewer than 16 records, or no fringes)</td></tr>"; return; }
  const volts = s.ellipse && s.ellipse.amp_sin_v !== null;
  body.innerHTML = s.readouts.map(r => {
    const d = r.unit === "" ? 4 : 3;
    let extra = "";
    if (volts && r.key === "amplitude_sin") extra = ` (${fmt(s.ellipse.amp_sin_v, 3)} V)`;
    if (volts && r.key === "amplitude_cos") extra = ` (${fmt(s.ellipse.amp_cos_v, 3)} V)`;
    return `<tr class="${r.ok ? "good" : "bad"}" id="ro-${r.key}" data-value="${r.value}"><th>${r.label}</th>` +
      `<td class="v">${fmt(r.value, d)} ${r.unit}${extra}</td><td>${gauge(r)}</td><td>${fmt(r.lo, d)} .. ${fmt(r.hi, d)}</td></tr>`;
  }).join("");
  const q = s.quality_pct;
  $("quality-bar").style.width = q + "%";
  $("quality-bar").style.background = q >= 50 ? "#2e7d32" : q >= 25 ? "#f9a825" : "#c62828";
  $("quality-text").textContent = fmt(q, 0) + " %";
  $("quality").dataset.value = q;
}

function dms(deg) {
  const sgn = deg < 0 ? "-" : "", a = Math.abs(deg), d = Math.floor(a), m = Math.floor((a - d) * 60), sec = (a - d - m / 60) * 3600;
  return `${sgn}${d}\u00b0 ${m}' ${sec.toFixed(2)}"`;
}

function motion(s) {
  const p = s.position, v = s.speed;
  if (!p) return;
  $("pos-counts").textContent = p.counts + " counts";
  $("pos-scaled").textContent = p.um !== null ? fmt(p.um, 3) + " um" : p.degrees !== null ? `${fmt(p.degrees, 5)} degree = ${dms(p.degrees)}` : "";
  $("speed-counts").textContent = fmt(v.counts_per_s, 0) + " counts/s" + (v.fringe_hz !== null ? ` (${fmt(v.fringe_hz, 1)} periods/s)` : "");
  $("speed-scaled").textContent = v.um_per_s !== null ? fmt(v.um_per_s / 1000, 4) + " mm/s" : v.degrees_per_s !== null ? fmt(v.degrees_per_s, 4) + " degree/s" : "";
}

function flags(s) {
  const f = Object.assign({}, s.flags || {});
  if (s.board_status) ["overspeed", "fifo_overflow"].forEach(k => { if (k in s.board_status) f[k] = s.board_status[k]; });
  $("flags").innerHTML = Object.keys(f).map(k => {
    const good = k === "present" ? f[k] : !f[k];
    return `<span class="flag ${good ? "good" : "on"}" id="flag-${k}">${k.replace("_", " ")}: ${f[k] ? "yes" : "no"}</span>`;
  }).join("");
  const l = s.link || {};
  $("link").tBodies[0].innerHTML = Object.keys(l).map(k => `<tr><th>${k.replace(/_/g, " ")}</th><td id="link-${k}">${typeof l[k] === "number" && !Number.isInteger(l[k]) ? fmt(l[k], 1) : l[k]}</td></tr>`).join("");
}

function burst(s) {
  const b = s.burst || {}, el = $("burst-status");
  if (el.dataset.state === b.state && el.dataset.file === (b.file || "")) return;
  el.dataset.state = b.state; el.dataset.file = b.file || "";
  el.textContent = b.state === "idle" ? "no burst yet" : `${b.state}: ${b.message || ""}`;
  $("burst-btn").disabled = b.state === "running";
  if (b.state === "done") { const f = $("report"); f.hidden = false; f.src = "/api/report?t=" + Date.now(); }
}

function show(s) {
  state = s;
  const st = $("status");
  st.dataset.connected = s.connected;
  st.className = s.connected ? "up" : "down";
  st.textContent = s.connected ? "connected" : "disconnected: " + s.message;
  // what is shown while disconnected is the last the board sent: greyed out
  document.querySelector("main").classList.toggle("stale", !s.connected);
  $("source").textContent = s.source || "-";
  // the burst length: at most what the source holds, until the user types one
  const n = $("burst-samples");
  if (s.setup && s.setup.burst_depth && !n.dataset.touched) n.value = Math.min(16384, s.setup.burst_depth);
  drawLissajous(s); readouts(s); motion(s); flags(s); burst(s);
  const f = $("tol-form");
  if (s.tolerances && !f.contains(document.activeElement))
    Object.keys(s.tolerances).forEach(k => { if (f.elements[k]) f.elements[k].value = s.tolerances[k]; });
}

function connect() {
  const ws = new WebSocket(`ws://${location.host}/api/live`);
  ws.onmessage = m => show(JSON.parse(m.data));
  ws.onclose = () => {
    const st = $("status"); st.className = "down"; st.dataset.connected = "false"; st.textContent = "monitor server unreachable; retrying";
    document.querySelector("main").classList.add("stale");
    setTimeout(connect, 1000);
  };
}

async function post(url, body) {
  const r = await fetch(url, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
  const j = await r.json();
  if (!r.ok) throw new Error(j.error || r.statusText);
  return j;
}

$("burst-samples").addEventListener("input", () => { $("burst-samples").dataset.touched = "yes"; });
$("burst-form").addEventListener("submit", async ev => {
  ev.preventDefault();
  try {
    await post("/api/burst", { samples: Number($("burst-samples").value), trigger: $("burst-trigger").value, pre: Number($("burst-pre").value) });
  } catch (e) { const el = $("burst-status"); el.dataset.state = "rejected"; el.textContent = "rejected: " + e.message; }
});
$("save-btn").addEventListener("click", async () => {
  try { const j = await post("/api/save", {}); $("save-status").textContent = "saved: " + j.files.join(", "); }
  catch (e) { $("save-status").textContent = "not saved: " + e.message; }
});
$("tol-form").addEventListener("submit", async ev => {
  ev.preventDefault();
  const body = {};
  for (const el of ev.target.elements) if (el.name && el.value !== "") body[el.name] = Number(el.value);
  try { await post("/api/tolerances", body); $("tol-status").textContent = "set"; document.activeElement.blur(); }
  catch (e) { $("tol-status").textContent = e.message; }
});
connect();
