// The page: a robot picker and a YAML editor on the left, the drawing of the arm under them, the
// results on the right, typeset by MathJax. dhsym itself runs in worker.js; every request is
// answered by dhsym.web.app.handle, and every answer is JSON.
//
// Deep links: index.html?robot=NAME&show=table|links|fk|jacobian|ik (with &from=I&to=J for fk,
// &frame=K&point=P for the Jacobian), and #yaml=... (a robot file, URL-encoded) for an arm of one's
// own. The result stands in #result, whose data-state is "loading", "working", "ready" or "error".
"use strict";

const SHOWS = ["table", "links", "fk", "jacobian", "ik"];
const SHOW_FRAMES = { fk: ["from", "to"], jacobian: ["frame", "point"] }; // the frames each output takes
const DEFAULT_ROBOT = "puma560";
const EDIT_PAUSE_MS = 500; // typing pauses this long before the result is worked out again
const $ = (id) => document.getElementById(id);

const state = {
  robots: [], // [{name, title, yaml}] from robots.json
  show: "fk",
  worker: null,
  ready: false,
  nextId: 1,
  pending: {}, // channel -> {id, request, resolve} waiting for the worker
  busy: {}, // channel -> id of the request the worker is working on
  latex: "",
  frames: null,
  framesChosen: false, // the reader picked from/to; else the whole chain, whatever its frames
  sliderNames: "",
  editTimer: null,
};

// ---------------------------------------------------------------- the worker

function startWorker() {
  state.ready = false;
  state.busy = {};
  try {
    state.worker = new Worker("worker.js", { type: "module" });
  } catch (error) { // a page opened as a file, or a browser without module workers
    failed(error.message);
    return;
  }
  state.worker.onmessage = (event) => onWorkerMessage(event.data);
  state.worker.onerror = (event) => {
    if (!state.ready) failed(event.message || "the Python runtime could not be started");
  };
  setStatus("loading", "Loading Python and SymPy (once; the browser keeps them)…");
}

function onWorkerMessage(message) {
  if (message.kind === "progress") {
    // the bytes fill 80 % of the bar; starting Python and importing SymPy the rest
    $("progress").value = Math.max($("progress").value, 0.8 * (message.loaded / message.total));
    const mb = (bytes) => (bytes / 1e6).toFixed(1);
    state.bytes = `${mb(message.loaded)} of ${mb(message.total)} MB`;
    setStatus("loading", `Loading Python and SymPy: ${state.bytes}`);
  } else if (message.kind === "stage") {
    if (message.text.startsWith("Importing")) $("progress").value = 0.9;
    setStatus("loading", `${message.text}… ${state.bytes ? `(${state.bytes} loaded)` : ""}`);
  } else if (message.kind === "ready") {
    state.ready = true;
    window.dhsymTimings = message.timings; // for benchmarks/web_speed.py
    $("progress").value = 1;
    $("versions").textContent = `dhsym ${message.versions.dhsym}, Pyodide ${message.versions.pyodide}; Python ready in ${message.seconds.toFixed(1)} s.`;
    setStatus("ready", "Ready");
    for (const channel of Object.keys(state.pending)) send(channel);
  } else if (message.kind === "failed") {
    failed(message.message);
  } else if (message.kind === "answer") {
    const channel = Object.keys(state.busy).find((c) => state.busy[c] && state.busy[c].id === message.id);
    if (!channel) return;
    const job = state.busy[channel];
    delete state.busy[channel];
    if (state.pending[channel]) send(channel); // a newer request replaces this one's answer
    else job.resolve(JSON.parse(message.answer));
    updateStop();
  }
}

function failed(why) {
  state.failed = true;
  const where = location.protocol === "file:"
    ? "This page was opened as a file; browsers load its Python only from a web server. In its folder run " +
      "`python3 -m http.server` and open http://localhost:8000/."
    : "Python could not be loaded in this browser (it needs WebAssembly, as in any current browser).";
  setStatus("error", "Python could not be loaded");
  showMessage($("result"), "error", where, why);
}

// Asks the worker; a newer request on the same channel replaces one not yet sent.
function ask(channel, request) {
  return new Promise((resolve) => {
    state.pending[channel] = { request, resolve };
    if (state.ready && !state.busy[channel]) send(channel);
  });
}

function send(channel) {
  const job = state.pending[channel];
  if (!job || state.busy[channel] || !state.ready) return;
  delete state.pending[channel];
  job.id = state.nextId++;
  state.busy[channel] = job;
  state.worker.postMessage({ id: job.id, request: JSON.stringify(job.request) });
  updateStop();
}

function updateStop() {
  const working = Object.keys(state.busy).length > 0;
  $("stop").hidden = !working;
  if (working) setStatus("working", "Working it out…");
  else if (state.ready) setStatus("ready", "Ready");
}

function stopWorker() {
  state.worker.terminate();
  const channels = Object.keys(state.busy);
  for (const channel of channels) state.pending[channel] = state.pending[channel] || state.busy[channel];
  delete state.pending.show; // the result that took too long is not asked for again by itself
  showMessage($("result"), "error", "Stopped. Python starts again; change the robot or the output to go on.");
  $("stop").hidden = true;
  startWorker();
}

function setStatus(kind, text) {
  $("status").dataset.state = kind;
  $("status-text").textContent = text;
  $("progress").hidden = kind !== "loading";
}

// ---------------------------------------------------------------- the robot file

function robotFile() {
  const picked = state.robots.find((r) => r.name === $("robot").value);
  const text = $("yaml").value;
  return { yaml: text, file: picked && picked.yaml === text ? `${picked.name}.yaml` : "robot.yaml" };
}

// A band behind the line of the robot file's error, under the text, moving with it as it scrolls.
function markLine(line) {
  const band = $("error-band");
  band.hidden = !line;
  if (!line) return;
  const style = getComputedStyle($("yaml"));
  const height = parseFloat(style.lineHeight);
  band.style.height = `${height}px`;
  band.style.top = `${parseFloat(style.paddingTop) + (line - 1) * height - $("yaml").scrollTop}px`;
  band.dataset.line = line;
}

function fillGutter(errorLine) {
  markLine(errorLine);
  const lines = $("yaml").value.split("\n").length;
  const gutter = $("gutter");
  gutter.textContent = "";
  for (let n = 1; n <= lines; n++) {
    const line = document.createElement("span");
    line.textContent = n + "\n";
    if (n === errorLine) line.className = "error-line";
    gutter.appendChild(line);
  }
  gutter.scrollTop = $("yaml").scrollTop;
}

function goToLine(line, column) {
  const text = $("yaml").value;
  let start = 0;
  for (let n = 1; n < line; n++) start = text.indexOf("\n", start) + 1;
  const end = text.indexOf("\n", start);
  const at = start + Math.max(0, (column || 1) - 1);
  $("yaml").focus();
  $("yaml").setSelectionRange(at, end < 0 ? text.length : Math.max(at, end));
}

function showProblem(answer) {
  const box = $("problem");
  box.textContent = "";
  const lines = [];
  if (answer && answer.state === "error" && answer.line) lines.push(["error", answer.message]); // the file's own
  for (const warning of (answer && answer.warnings) || []) lines.push(["warning", warning]);
  for (const [kind, text] of lines) {
    const p = document.createElement("p");
    p.className = kind;
    p.textContent = (kind === "error" ? "error: " : "warning: ") + text;
    if (kind === "error" && answer.line) {
      p.title = "click to go to the line";
      p.onclick = () => goToLine(answer.line, answer.column);
    }
    box.appendChild(p);
  }
  fillGutter(answer && answer.state === "error" ? answer.line : null);
}

function pickRobot(name) {
  const robot = state.robots.find((r) => r.name === name);
  if (!robot) return;
  $("robot").value = name;
  $("yaml").value = robot.yaml;
  state.frames = null;
  state.framesChosen = false;
  for (const id of ["from", "to", "frame", "point"]) $(id).textContent = "";
  onEdit(true);
}

function onEdit(now) {
  const picked = state.robots.find((r) => r.name === $("robot").value);
  if (picked && picked.yaml !== $("yaml").value) { // edited: the robot is the user's own from here on
    if (!$("robot").querySelector('option[value=""]')) addCustomOption();
    $("robot").value = "";
  }
  fillGutter(null);
  $("result").dataset.state = "working";
  clearTimeout(state.editTimer);
  state.editTimer = setTimeout(() => { updateLink(); refresh(); }, now === true ? 0 : EDIT_PAUSE_MS);
}

function addCustomOption() {
  const option = document.createElement("option");
  option.value = "";
  option.textContent = "(your robot)";
  $("robot").prepend(option);
}

// ---------------------------------------------------------------- results

function widthPt() {
  const chosen = $("width").value;
  if (chosen !== "auto") return Number(chosen);
  const px = $("result").clientWidth - 24;
  return Math.max(100, Math.round((px / mathEm()) * 10)); // the layout's line is in pt of 10 pt type
}

// The width in px of 1 em of typeset math: MathJax sizes its formulas in ex of the page's font, whose
// x-height is not Computer Modern's, so a 20 em space is measured once.
let measuredEm = null;
function mathEm() {
  if (measuredEm) return measuredEm;
  const fontPx = parseFloat(getComputedStyle($("result")).fontSize);
  if (!window.MathJax || !MathJax.tex2svg) return fontPx * 1.2; // before MathJax: about what it gives
  const probe = MathJax.tex2svg("\\kern20em", { display: false });
  probe.style.visibility = "hidden";
  $("result").appendChild(probe);
  measuredEm = probe.querySelector("svg").getBoundingClientRect().width / 20 || fontPx;
  probe.remove();
  return measuredEm;
}

async function refresh() {
  const result = $("result");
  result.dataset.state = "working";
  const asked = performance.now();
  const request = { kind: "show", show: state.show, width: widthPt(), ...robotFile() };
  Object.assign(request, chosenFrames(), state.show === "ik" ? { free: freeVariables() } : {});
  const answering = ask("show", request);
  refreshDrawing(); // after the result: the worker answers in the order asked
  const answer = await answering;
  showProblem(answer);
  if (answer.state === "error") {
    state.latex = "";
    showMessage(result, "error", answer.message, answer.traceback);
    const hint = pageWords(answer.message);
    if (hint) result.appendChild(Object.assign(document.createElement("p"), { className: "hint", textContent: hint }));
    return;
  }
  updateFrames(answer.frames);
  state.latex = answer.latex;
  await mathReady();
  const content = document.createDocumentFragment();
  const title = document.createElement("h2");
  appendSegments(title, answer.title);
  content.appendChild(title);
  for (const part of answer.parts) content.appendChild(partElement(part));
  result.textContent = "";
  result.appendChild(content);
  result.dataset.seconds = ((performance.now() - asked) / 1000).toFixed(3); // request to typeset
  result.dataset.state = "ready";
}

// MathJax, with its stylesheet for the SVG it makes (typeset piece by piece, the page adds it itself).
let mathStyles = null;
async function mathReady() {
  await MathJax.startup.promise;
  if (!mathStyles) {
    mathStyles = MathJax.svgStylesheet();
    document.head.appendChild(mathStyles);
  }
}

function partElement(part) {
  if (part.kind === "math") {
    const div = document.createElement("div");
    div.className = "display";
    div.appendChild(MathJax.tex2svg(part.tex, { display: true }));
    return div;
  }
  const element = document.createElement(part.kind === "heading" ? "h3" : "p");
  appendSegments(element, part.segments);
  return element;
}

function appendSegments(element, segments) {
  for (const [kind, text] of segments) {
    element.appendChild(kind === "math" ? MathJax.tex2svg(text, { display: false }) : document.createTextNode(text));
  }
}

// The command line's options that a message may name, and where the page has them.
const PAGE_WORDS = [
  [/--free/, "--free is the field “free joint variables” (Inverse kinematics)"],
  [/--from|--to\b/, "--from and --to are “from frame” and “to” (Forward kinematics)"],
  [/dhsym links/, "'dhsym links' is the tab Link matrices"],
  [/--frame|--point/, "--frame and --point are “in frame” and “velocity of frame” (Jacobian)"],
];

function pageWords(message) {
  const found = PAGE_WORDS.filter(([pattern]) => pattern.test(message)).map(([, words]) => words);
  return found.length ? `In this page: ${found.join("; ")}.` : "";
}

function showMessage(element, kind, text, details) {
  element.textContent = "";
  const p = document.createElement("p");
  p.className = `message ${kind}`;
  p.textContent = text;
  element.appendChild(p);
  if (details) {
    const more = document.createElement("details");
    const summary = document.createElement("summary");
    summary.textContent = "what Python said";
    const pre = document.createElement("pre");
    pre.textContent = details;
    more.append(summary, pre);
    element.appendChild(more);
  }
  element.dataset.state = kind;
}

// The frames of ⁱTⱼ for the forward kinematics: what the reader chose, else (null) the whole chain.
function chosenFrames() {
  if (!state.framesChosen) return {};
  if (state.show === "fk") return { from: $("from").value || null, to: $("to").value || null };
  if (state.show === "jacobian") return { frame: $("frame").value || null, point: $("point").value || null };
  return {};
}

function freeVariables() {
  return $("free").value.split(/[\s,]+/).filter(Boolean);
}

function updateFrames(frames) {
  if (!frames || JSON.stringify(frames) === JSON.stringify(state.frames)) return;
  const last = frames.length - 1;
  for (const [id, index] of [["from", 0], ["to", last], ["frame", 0], ["point", last]]) {
    const select = $(id);
    const keep = state.framesChosen ? select.value : null;
    select.textContent = "";
    for (const frame of frames) {
      const option = document.createElement("option");
      option.value = option.textContent = String(frame);
      select.appendChild(option);
    }
    select.value = frames.map(String).includes(keep) ? keep : String(frames[index]);
  }
  state.frames = frames;
}

function selectTab(show) {
  state.show = SHOWS.includes(show) ? show : "fk";
  for (const tab of document.querySelectorAll("#tabs button")) {
    tab.setAttribute("aria-selected", String(tab.dataset.show === state.show));
  }
  document.body.dataset.show = state.show;
}

// ---------------------------------------------------------------- the drawing

async function refreshDrawing() {
  const values = {};
  for (const input of document.querySelectorAll("#sliders input")) {
    values[input.name] = input.dataset.unit === "°" ? (Number(input.value) * Math.PI) / 180 : Number(input.value);
  }
  const answer = await ask("draw", { kind: "draw", values, view: $("view").value, ...robotFile() });
  if (answer.state === "error" && answer.line && $("arm").querySelector("svg")) {
    $("arm").dataset.state = "stale"; // the robot file has a mistake: the last picture stays, faded
    return;
  }
  if (answer.state === "error") {
    showMessage($("arm"), "note", answer.line ? "The arm is drawn once the robot file reads." : answer.message);
    $("sliders").textContent = "";
    state.sliderNames = "";
    return;
  }
  $("arm").innerHTML = answer.svg; // dhsym's own SVG: numbers and escaped labels only
  $("arm").dataset.state = "ready";
  const names = answer.sliders.map((s) => s.name).join(" ");
  if (names !== state.sliderNames) buildSliders(answer.sliders);
}

function buildSliders(sliders) {
  const box = $("sliders");
  box.textContent = "";
  state.sliderNames = sliders.map((s) => s.name).join(" ");
  for (const s of sliders) {
    const label = document.createElement("label");
    const name = document.createElement("span");
    name.textContent = s.label;
    const input = document.createElement("input");
    Object.assign(input, { type: "range", name: s.name, min: s.min, max: s.max, step: s.step, value: s.value });
    input.dataset.unit = s.unit;
    const shown = document.createElement("output");
    const show = () => {
      const value = Number(input.value).toFixed(s.unit === "°" ? 0 : 2);
      shown.textContent = `${Number(value) === 0 ? value.replace("-", "") : value}${s.unit}`;
    };
    show();
    input.oninput = () => { show(); refreshDrawing(); };
    label.append(name, input, shown);
    box.appendChild(label);
  }
}

// ---------------------------------------------------------------- links, copying, slides

function currentLink() {
  const url = new URL(location.href);
  url.search = "";
  url.hash = "";
  const file = robotFile();
  const params = new URLSearchParams();
  if (file.file !== "robot.yaml") params.set("robot", $("robot").value);
  params.set("show", state.show);
  if (state.frames && state.framesChosen) {
    const ends = { from: state.frames[0], to: state.frames.at(-1), frame: state.frames[0], point: state.frames.at(-1) };
    for (const id of SHOW_FRAMES[state.show] || []) {
      if ($(id).value !== String(ends[id])) params.set(id, $(id).value);
    }
  }
  url.search = params.toString();
  if (file.file === "robot.yaml") url.hash = "yaml=" + encodeURIComponent(file.yaml);
  return url.href;
}

function updateLink() {
  history.replaceState(null, "", currentLink());
}

async function copyText(text, button) {
  try {
    await navigator.clipboard.writeText(text);
  } catch {
    const area = document.createElement("textarea"); // where the clipboard API is not offered (plain http)
    area.value = text;
    document.body.appendChild(area);
    area.select();
    document.execCommand("copy");
    area.remove();
  }
  const label = button.textContent;
  button.textContent = "Copied";
  setTimeout(() => { button.textContent = label; }, 1500);
}

async function downloadSlides() {
  const button = $("slides");
  button.disabled = true;
  const request = { kind: "slides", jacobian: state.show === "jacobian", ik: state.show === "ik", ...robotFile() };
  Object.assign(request, chosenFrames(), state.show === "ik" ? { free: freeVariables() } : {});
  const answer = await ask("slides", request);
  button.disabled = false;
  if (answer.state === "error") {
    showProblem(answer);
    return;
  }
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([answer.tex], { type: "application/x-tex" }));
  link.download = `${$("robot").value || "robot"}.tex`;
  document.body.appendChild(link);
  link.click();
  link.remove();
}

// ---------------------------------------------------------------- start

async function main() {
  startWorker();
  if (state.failed) return;
  // MathJax's first formula sets up its parser and fonts: done while Python loads, not after.
  window.addEventListener("load", () => MathJax.startup.promise.then(() => MathJax.tex2svg("x^2")));
  selectTab(new URLSearchParams(location.search).get("show") || "fk");
  try {
    state.robots = await (await fetch("robots.json")).json();
  } catch {
    failed("robots.json could not be read");
    return;
  }
  for (const robot of state.robots) {
    const option = document.createElement("option");
    option.value = robot.name;
    option.textContent = `${robot.name}: ${robot.title}`;
    $("robot").appendChild(option);
  }
  const params = new URLSearchParams(location.search);
  const hash = new URLSearchParams(location.hash.slice(1));
  if (hash.has("yaml")) {
    addCustomOption();
    $("robot").value = "";
    $("yaml").value = hash.get("yaml");
    onEdit(true);
  } else {
    const name = params.get("robot");
    const known = state.robots.some((r) => r.name === name);
    pickRobot(known ? name : DEFAULT_ROBOT);
    if (name && !known) showProblem({ state: "error", message: `unknown robot '${name}' in the link; showing ${DEFAULT_ROBOT}` });
  }
  for (const id of ["from", "to", "frame", "point"]) { // ?from=I&to=J: kept once the robot's frames are known
    if (!params.get(id)) continue;
    state.framesChosen = true;
    const option = document.createElement("option");
    option.value = option.textContent = params.get(id);
    $(id).appendChild(option);
  }
  $("robot").onchange = () => { if ($("robot").value) pickRobot($("robot").value); };
  $("yaml").oninput = () => onEdit(false);
  $("yaml").onscroll = () => {
    $("gutter").scrollTop = $("yaml").scrollTop;
    markLine(Number($("error-band").dataset.line) || null);
  };
  for (const tab of document.querySelectorAll("#tabs button")) {
    tab.onclick = () => { selectTab(tab.dataset.show); updateLink(); refresh(); };
  }
  for (const id of ["from", "to", "frame", "point"]) {
    $(id).onchange = () => { state.framesChosen = true; updateLink(); refresh(); };
  }
  $("width").onchange = () => refresh();
  $("free").onchange = () => refresh();
  $("view").onchange = () => refreshDrawing();
  $("stop").onclick = stopWorker;
  $("share").onclick = () => copyText(currentLink(), $("share"));
  $("copy").onclick = () => copyText(state.latex, $("copy"));
  $("slides").onclick = downloadSlides;
  let lastWidth = $("result").clientWidth;
  let resizing = null;
  window.addEventListener("resize", () => { // laid out again once the window has settled, if much wider or narrower
    clearTimeout(resizing);
    resizing = setTimeout(() => {
      const width = $("result").clientWidth;
      if ($("width").value === "auto" && Math.abs(width - lastWidth) > 0.1 * lastWidth) {
        lastWidth = width;
        refresh();
      }
    }, 300);
  });
}

main();
