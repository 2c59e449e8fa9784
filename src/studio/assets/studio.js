// The studio's page: the gallery, the scene as a form beside its text, the sheets re-drawn
// after each edit (debounced), the report beside them, the downloads. Every string of a
// scene reaches the page as text (textContent), never as markup; the sheets' SVG is the
// program's own, its texts escaped by the SVG writer.
"use strict";

// The page's words, from the catalogue (`words/studio.rs`): key → [ru, uk, en].
const WORDS = window.TMM_WORDS;
const LANGS = ["ru", "uk", "en"];

const state = { stem: "", toml: "", fields: [], sheets: [], shown: 0, zoom: 0.25, pan: [10, 10], timer: 0, seq: 0 };
const $ = (id) => document.getElementById(id);
const lang = () => $("lang").value;
const word = (w) => WORDS[w][LANGS.indexOf(lang())];

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v; else if (k.startsWith("on")) e.addEventListener(k.slice(2), v); else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function words() {
  document.documentElement.lang = lang();
  for (const e of document.querySelectorAll("[data-word]")) e.textContent = word(e.dataset.word);
}

async function post(url, body) {
  const r = await fetch(url, { method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body) });
  if (!r.ok) throw new Error(await r.text());
  return r;
}

// The gallery: one section per kind, a card per scene with its first sheet.
async function gallery() {
  $("editor").hidden = true;
  $("gallery").hidden = false;
  const cards = await (await fetch("/api/gallery?lang=" + lang())).json();
  const g = $("gallery");
  g.replaceChildren();
  let section = null;
  for (const c of cards) {
    if (!section || section.dataset.group !== c.group) {
      g.append(el("h2", {}, c.heading));
      section = el("div", { class: "cards" });
      section.dataset.group = c.group;
      g.append(section);
    }
    section.append(el("div", { class: "card", "data-stem": c.stem },
      el("img", { src: "/api/thumb/" + c.stem, alt: c.title, loading: "lazy" }),
      el("span", { class: "title" }, c.title),
      el("button", { class: "from", onclick: () => openScene(c.stem) }, word("from"))));
  }
}

async function openScene(stem) {
  const r = await fetch("/api/scene/" + encodeURIComponent(stem));
  state.stem = stem;
  state.sheets = [];
  state.shown = 0;
  $("gallery").hidden = true;
  $("editor").hidden = false;
  $("canvas").replaceChildren();
  await setText(await r.text());
}

// A new text: the form rebuilt from it, the sheets redrawn.
async function setText(toml) {
  state.toml = toml;
  state.edited = null;
  if ($("text").value !== toml) $("text").value = toml;
  try {
    state.fields = await (await post("/api/fields", { toml })).json();
    form();
  } catch (e) {
    showProblems([{ key: null, message: e.message }]);
    return;
  }
  redraw();
}

function form() {
  const f = $("form");
  f.replaceChildren();
  let set = null;
  for (const field of state.fields) {
    if (!set || set.dataset.section !== field.section) {
      set = el("fieldset", {}, el("legend", {}, field.section || "—"));
      set.dataset.section = field.section;
      f.append(set);
    }
    const input = el("input", { name: field.key, value: field.value.replace(/^"(.*)"$/, "$1") });
    if (field.number) input.setAttribute("inputmode", "decimal");
    input.addEventListener("input", () => edit(field.key, input.value, field.value.startsWith('"')));
    const row = el("div", { class: "field", "data-key": field.key },
      el("label", { for: field.key, title: field.key }, field.key.split(".").pop()),
      input);
    input.id = field.key;
    if (field.unit) row.querySelector("label").append(el("span", { class: "unit" }, ", " + field.unit));
    if (field.meaning || field.default) {
      const d = field.default ? " [" + field.default + "]" : "";
      row.append(el("span", { class: "meaning" }, field.meaning + d));
    }
    set.append(row);
  }
}

let editTimer = 0;
function edit(key, value, quoted) {
  state.edited = key;
  clearTimeout(editTimer);
  editTimer = setTimeout(async () => {
    const v = quoted ? JSON.stringify(value) : value;
    try {
      const r = await (await post("/api/set", { toml: state.toml, key, value: v })).json();
      state.toml = r.toml;
      $("text").value = r.toml;
      redraw();
    } catch (e) {
      showProblems([{ key, message: e.message }]);
    }
  }, 250);
}

function job() {
  return { toml: state.toml, stem: state.stem, lang: lang(), drafting: parseFloat($("drafting").value) };
}

// The sheets and report of the current text; a failure keeps the last good sheets.
function redraw() {
  clearTimeout(state.timer);
  state.timer = setTimeout(async () => {
    const seq = ++state.seq;
    $("status").textContent = word("drawing");
    let r;
    try {
      r = await (await post("/api/render", job())).json();
    } catch (e) {
      $("status").textContent = word("busy") + ": " + e.message;
      return;
    }
    if (seq !== state.seq) return;
    showProblems(r.problems);
    if (r.problems.length) {
      $("status").textContent = word("kept");
      return;
    }
    state.sheets = r.sheets;
    if (state.shown >= r.sheets.length) state.shown = 0;
    $("status").textContent = word("drawn") + " " + r.ms.toFixed(0) + " " + word("ms");
    sheets();
    report(r.report);
    downloads();
  }, 150);
}

function showProblems(problems) {
  for (const row of document.querySelectorAll(".field.bad")) {
    row.classList.remove("bad");
    row.querySelector(".message")?.remove();
  }
  const loose = [];
  for (const p of problems) {
    // A problem names its key; a construction that fails names none, and is shown at the
    // field whose edit made it fail.
    const named = state.fields.map((f) => f.key).filter((k) => p.message.includes(k)).sort((a, b) => b.length - a.length)[0];
    const key = p.key || named || state.edited;
    const row = key && document.querySelector('.field[data-key="' + CSS.escape(key) + '"]');
    if (row) {
      row.classList.add("bad");
      row.append(el("span", { class: "message" }, p.message));
    } else loose.push(p.message);
  }
  $("problems").textContent = loose.join("\n");
}

function sheets() {
  const tabs = $("sheet-tabs");
  tabs.replaceChildren();
  state.sheets.forEach((s, i) => {
    tabs.append(el("button", { class: i === state.shown ? "on" : "", onclick: () => { state.shown = i; sheets(); } }, s.name));
  });
  const doc = new DOMParser().parseFromString(state.sheets[state.shown].svg, "image/svg+xml");
  const svg = doc.documentElement;
  for (const bad of svg.querySelectorAll("script, foreignObject")) bad.remove();
  const first = !$("canvas").firstChild;
  $("canvas").replaceChildren(document.importNode(svg, true));
  if (first) fit();
  place();
  if (state.reading && state.reading.sheet === state.shown) drawReading(state.reading);
  loadReplay();
}

// The replay: the figures of the shown sheet with their protocols; a figure chosen is drawn
// up to its current step, the step in red and its sentence marked in the step list.
const replay = { views: [], view: null, at: 0, timer: 0 };

async function loadReplay() {
  stopPlay();
  replay.views = [];
  replay.view = null;
  const sheet = state.shown;
  let views = [];
  try {
    views = window.TMM_DATA ? window.TMM_DATA.replays[sheet] : await (await post("/api/replay", { ...job(), sheet })).json();
  } catch (e) {
    views = [];
  }
  if (sheet !== state.shown) return;
  replay.views = views;
  const sel = $("figure");
  const before = sel.value;
  sel.replaceChildren(el("option", { value: "" }, word("whole")));
  for (const v of views) sel.append(el("option", { value: String(v.view) }, v.caption || "view " + v.view));
  // The figure chosen stays chosen when the scene is edited, at its last step.
  if (views.some((v) => String(v.view) === before)) {
    sel.value = before;
    chooseFigure();
  } else showReplay();
}

function chooseFigure() {
  const k = $("figure").value;
  replay.view = k === "" ? null : replay.views.find((v) => String(v.view) === k);
  replay.at = replay.view ? replay.view.steps.length - 1 : 0;
  stopPlay();
  showReplay();
}

function showReplay() {
  const svg = $("canvas").querySelector("svg");
  const list = $("r-steps");
  const v = replay.view;
  if (!svg) return;
  for (const e of svg.querySelectorAll(".replay-hidden, .replay-dim, .replay-now")) e.classList.remove("replay-hidden", "replay-dim", "replay-now");
  $("r-slider").max = v ? String(v.steps.length - 1) : "0";
  $("r-slider").value = String(replay.at);
  if (!v) {
    list.replaceChildren();
    $("r-count").textContent = "";
    return;
  }
  for (const g of svg.querySelectorAll(":scope > g[id^='view-']")) {
    if (g.id !== "view-" + v.view) g.classList.add("replay-dim");
  }
  const shown = new Set(v.steps.slice(0, replay.at + 1).map((s) => s.id));
  for (const s of v.steps) {
    const g = svg.getElementById("view-" + v.view + "-step-" + s.id);
    if (!g) continue;
    if (!shown.has(s.id)) g.classList.add("replay-hidden");
    if (s.id === v.steps[replay.at].id) g.classList.add("replay-now");
  }
  v.labels.forEach((steps, n) => {
    if (steps.some((id) => shown.has(id))) return;
    for (const part of ["-labels-text-", "-labels-leader-"]) {
      svg.getElementById("view-" + v.view + part + (n + 1))?.classList.add("replay-hidden");
    }
  });
  $("r-count").textContent = replay.at + 1 + " / " + v.steps.length;
  if (list.dataset.view !== String(v.view) || list.children.length !== v.steps.length) {
    list.dataset.view = String(v.view);
    list.replaceChildren(...v.steps.map((s, i) => el("li", { "data-step": String(s.id), onclick: () => go(i) }, s.sentence)));
  }
  [...list.children].forEach((li, i) => {
    li.className = i === replay.at ? "now" : i > replay.at ? "later" : "";
  });
  list.children[replay.at]?.scrollIntoView({ block: "nearest" });
}

function go(i) {
  if (!replay.view) return;
  replay.at = Math.max(0, Math.min(replay.view.steps.length - 1, i));
  showReplay();
}

function stopPlay() {
  clearInterval(replay.timer);
  replay.timer = 0;
  $("r-play").textContent = "▶";
}

// Play to the next breakpoint: the end, or where the step's group (a position) changes.
function play() {
  if (replay.timer) return stopPlay();
  const v = replay.view;
  if (!v) return;
  if (replay.at >= v.steps.length - 1) go(0);
  $("r-play").textContent = "⏸";
  replay.timer = setInterval(() => {
    const next = replay.at + 1;
    if (next >= v.steps.length) return stopPlay();
    const breaks = v.steps[next].group !== v.steps[replay.at].group;
    go(next);
    if (breaks) stopPlay();
  }, 250);
}

// The sheet's whole width in the viewport.
function fit() {
  const svg = $("canvas").firstChild;
  const w = svg.width.baseVal.value || svg.getBoundingClientRect().width;
  state.zoom = (($("viewport").clientWidth - 20) / w) || 0.25;
  state.pan = [10, 10];
}

function place() {
  $("canvas").style.transform = "translate(" + state.pan[0] + "px," + state.pan[1] + "px) scale(" + state.zoom + ")";
}

function report(rep) {
  const head = $("rows").tHead;
  head.replaceChildren(el("tr", {}, el("th", {}, word("quantity")), el("th", {}, word("graphical")), el("th", {}, word("analytic")), el("th", {}, word("error"))));
  const body = $("rows").tBodies[0];
  body.replaceChildren();
  state.reading = null;
  $("canvas").querySelector("line.reading")?.remove();
  if (!rep) return;
  // Four significant digits, as a drawing's table; a residue of the solver (|x| < 1e-12) is 0.
  const fmt = (x) => (x === null ? "—" : Math.abs(x) < 1e-12 ? "0" : Number(x.toPrecision(4)).toString().replace(".", lang() === "en" ? "." : ","));
  for (const row of rep.rows) {
    const name = row.quantity + (row.position ? " (" + row.position + ")" : "");
    const pct = row.rel_error === null ? "—" : fmt(row.rel_error * 100);
    const tr = el("tr", {}, el("td", {}, name), el("td", {}, fmt(row.graphical)), el("td", {}, fmt(row.analytic)), el("td", {}, pct));
    // A row of a report that says where its values are read (`read_at`, null when computed)
    // shows it on a click or Enter.
    if ("read_at" in row) {
      tr.tabIndex = 0;
      tr.className = row.read_at ? "read" : "computed";
      if (row.read_at) tr.title = word("where");
      const show = () => showReading(tr, row);
      tr.addEventListener("click", show);
      tr.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); show(); } });
    }
    body.append(tr);
  }
}

// Where a row's value is read: its sheet shown, the segment measured drawn over it in red and
// brought to the middle of the viewport; a row computed says so in its place.
function showReading(tr, row) {
  for (const e of document.querySelectorAll("#rows tr.chosen")) e.classList.remove("chosen");
  document.querySelector("#rows tr.reading-note")?.remove();
  tr.classList.add("chosen");
  const at = row.read_at;
  if (!at) {
    state.reading = null;
    $("canvas").querySelector("line.reading")?.remove();
    const why = row.method === "formula" ? word("computed") : word("derived");
    tr.after(el("tr", { class: "reading-note", role: "status" }, el("td", { colspan: "4" }, why)));
    return;
  }
  state.reading = at;
  if (state.shown !== at.sheet) {
    state.shown = at.sheet;
    sheets();
  } else drawReading(at);
  toReading(at);
  $("viewport").scrollIntoView({ block: "nearest" });
}

// The segment `at` (sheet mm, the SVG's viewBox units) as a red line over the sheet.
function drawReading(at) {
  const svg = $("canvas").querySelector("svg");
  if (!svg) return;
  svg.querySelector("line.reading")?.remove();
  const line = document.createElementNS("http://www.w3.org/2000/svg", "line");
  const attrs = { class: "reading", x1: at.x1, y1: at.y1, x2: at.x2, y2: at.y2, stroke: "#e00000", "stroke-width": "0.8", "stroke-linecap": "round" };
  for (const [k, v] of Object.entries(attrs)) line.setAttribute(k, String(v));
  svg.append(line);
}

// Pan and zoom so that the segment `at` and 40 mm around it fill the viewport, centred.
function toReading(at) {
  const svg = $("canvas").querySelector("svg");
  const box = svg && svg.viewBox.baseVal;
  if (!box || !box.width) return;
  const px = (svg.width.baseVal.value || svg.getBoundingClientRect().width / state.zoom) / box.width;
  const v = $("viewport");
  const span = Math.max(Math.abs(at.x2 - at.x1), Math.abs(at.y2 - at.y1)) + 80;
  state.zoom = Math.min(v.clientWidth, v.clientHeight) / (span * px);
  const [cx, cy] = [(at.x1 + at.x2) / 2, (at.y1 + at.y2) / 2];
  state.pan = [v.clientWidth / 2 - cx * px * state.zoom, v.clientHeight / 2 - cy * px * state.zoom];
  place();
}

function downloads() {
  const d = $("downloads");
  d.replaceChildren();
  const items = [["scene", word("scene")], ["pdf", word("set")], ["note", word("note")], ["csv", word("csv")]];
  for (const s of state.sheets) items.push([s.name + ".svg", s.name + ".svg"], [s.name + ".png", s.name + ".png"]);
  for (const [what, label] of items) d.append(el("button", { class: "download", "data-what": what, onclick: () => download(what) }, label));
}

async function download(what) {
  try {
    const r = await post("/api/download", { ...job(), what });
    const name = (r.headers.get("content-disposition") || "").replace(/.*filename="([^"]+)".*/, "$1");
    const url = URL.createObjectURL(await r.blob());
    const a = el("a", { href: url, download: name });
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  } catch (e) {
    $("status").textContent = e.message;
  }
}

function panZoom() {
  const v = $("viewport");
  v.addEventListener("wheel", (e) => {
    e.preventDefault();
    const k = Math.exp(-e.deltaY * 0.0015);
    const r = v.getBoundingClientRect();
    const [x, y] = [e.clientX - r.left, e.clientY - r.top];
    state.pan = [x - (x - state.pan[0]) * k, y - (y - state.pan[1]) * k];
    state.zoom *= k;
    place();
  }, { passive: false });
  let drag = null;
  v.addEventListener("pointerdown", (e) => { drag = [e.clientX - state.pan[0], e.clientY - state.pan[1]]; v.setPointerCapture(e.pointerId); });
  v.addEventListener("pointermove", (e) => { if (drag) { state.pan = [e.clientX - drag[0], e.clientY - drag[1]]; place(); } });
  v.addEventListener("pointerup", () => { drag = null; });
}

function replayControls() {
  $("figure").onchange = chooseFigure;
  $("r-first").onclick = () => { stopPlay(); go(0); };
  $("r-back").onclick = () => { stopPlay(); go(replay.at - 1); };
  $("r-forward").onclick = () => { stopPlay(); go(replay.at + 1); };
  $("r-last").onclick = () => { stopPlay(); go(Infinity); };
  $("r-play").onclick = play;
  $("r-slider").oninput = () => { stopPlay(); go(parseInt($("r-slider").value, 10)); };
}

function tabs() {
  const show = (text) => {
    $("form").hidden = text;
    $("text").hidden = !text;
    $("tab-form").classList.toggle("on", !text);
    $("tab-text").classList.toggle("on", text);
  };
  $("tab-form").onclick = () => show(false);
  $("tab-text").onclick = () => show(true);
  let t = 0;
  $("text").addEventListener("input", () => { clearTimeout(t); t = setTimeout(() => setText($("text").value), 300); });
}

$("lang").onchange = () => { words(); if ($("editor").hidden) gallery(); else redraw(); };
$("drafting").onchange = () => redraw();
$("to-gallery").onclick = () => gallery();
words();
tabs();
replayControls();
panZoom();
if (window.TMM_DATA) offline(); else gallery();

// The page written by `tmm render --format html`: the scene's sheets, replays and report
// are in the page itself, nothing is asked of a server.
function offline() {
  state.sheets = window.TMM_DATA.sheets;
  state.shown = 0;
  sheets();
  report(window.TMM_DATA.report);
}
