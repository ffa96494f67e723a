// dhsym's Python in web/worker.js: starting it (with a progress bar and a clear message where it cannot
// start), asking it (one request at a time per channel, a newer request replacing one not yet sent),
// and stopping a long piece of work by ending the worker.
import { $, mark, setStatus, showMessage, state } from "./page.js";

export function startWorker() {
  state.ready = false;
  state.busy = {};
  const started = window.dhsymStarted; // the first worker, started by index.html before the page loaded
  window.dhsymStarted = null;
  try {
    state.worker = started ? started.worker : new Worker("worker.js", { type: "module" });
  } catch (error) { // a page opened as a file, or a browser without module workers
    failed(error.message);
    return;
  }
  state.worker.onmessage = (event) => onWorkerMessage(event.data);
  state.worker.onerror = (event) => {
    if (!state.ready) failed(event.message || "the Python runtime could not be started");
  };
  setStatus("loading", "Loading Python and SymPy (once; the browser keeps them)…");
  for (const message of started ? started.early : []) onWorkerMessage(message);
}

function onWorkerMessage(message) {
  if (message.kind === "progress") {
    // the bytes fill 80 % of the bar; starting Python and importing SymPy the rest
    $("progress").value = Math.max($("progress").value, 0.8 * (message.loaded / message.total));
    const mb = (bytes) => (bytes / 1e6).toFixed(1);
    state.bytes = `${mb(message.loaded)} of ${mb(message.total)} MB`;
    setStatus("loading", `Loading Python and SymPy: ${state.bytes}`);
  } else if (message.kind === "stage") {
    $("progress").value = Math.max($("progress").value, 0.8);
    setStatus("loading", `${message.text}… ${state.bytes ? `(${state.bytes} loaded)` : ""}`);
  } else if (message.kind === "ready") {
    state.ready = true;
    window.dhsymTimings = message.timings; // the worker's own steps, for benchmarks/web_speed.py
    mark("python ready");
    $("progress").value = 1;
    $("versions").textContent = `dhsym ${message.versions.dhsym}, Pyodide ${message.versions.pyodide}; Python ready in ${message.seconds.toFixed(1)} s.`;
    setStatus("ready", "Ready");
    updateStop();
  } else if (message.kind === "failed") {
    failed(message.message);
  } else if (message.kind === "answer") {
    mark("first answer");
    const channel = Object.keys(state.busy).find((c) => state.busy[c] && state.busy[c].id === message.id);
    if (!channel) return;
    const job = state.busy[channel];
    delete state.busy[channel];
    if (state.pending[channel]) send(channel); // a newer request replaces this one's answer
    else job.resolve(JSON.parse(message.answer));
    updateStop();
  }
}

export function failed(why) {
  state.failed = true;
  const where = location.protocol === "file:"
    ? "This page was opened as a file; browsers load its Python only from a web server. In its folder run " +
      "`python3 -m http.server` and open http://localhost:8000/."
    : "Python could not be loaded in this browser (it needs WebAssembly, as in any current browser).";
  setStatus("error", "Python could not be loaded");
  showMessage($("result"), "error", where, why);
}

// Asks the worker; a newer request on the same channel replaces one not yet sent. A request made while
// Python loads is sent at once: the worker answers it as soon as Python is up.
export function ask(channel, request) {
  return new Promise((resolve) => {
    state.pending[channel] = { request, resolve };
    if (!state.busy[channel]) send(channel);
  });
}

function send(channel) {
  const job = state.pending[channel];
  if (!job || state.busy[channel] || state.failed) return;
  delete state.pending[channel];
  job.id = state.nextId++;
  state.busy[channel] = job;
  state.worker.postMessage({ id: job.id, request: JSON.stringify(job.request) });
  updateStop();
}

function updateStop() {
  if (!state.ready) return; // the progress bar until Python is up
  const working = Object.keys(state.busy).length > 0;
  $("stop").hidden = !working;
  if (working) setStatus("working", "Working it out…");
  else if (state.ready) setStatus("ready", "Ready");
}

export function stopWorker() {
  state.worker.terminate();
  const channels = Object.keys(state.busy);
  for (const channel of channels) state.pending[channel] = state.pending[channel] || state.busy[channel];
  delete state.pending.show; // the result that took too long is not asked for again by itself
  showMessage($("result"), "error", "Stopped. Python starts again; change the robot or the output to go on.");
  $("stop").hidden = true;
  startWorker();
  for (const channel of Object.keys(state.pending)) send(channel);
}
