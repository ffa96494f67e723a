// What every part of the page shares: the element lookup, the state, the status line, messages, and
// the robot file in the editor.

export const $ = (id) => document.getElementById(id);

// When the page reached each step of its start, in seconds since it was opened (the page's clock), for
// benchmarks/web_speed.py; the first time only.
window.dhsymMarks = window.dhsymMarks || {};
export function mark(name) {
  if (!(name in window.dhsymMarks)) window.dhsymMarks[name] = performance.now() / 1000;
}

export const state = {
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

export function setStatus(kind, text) {
  $("status").dataset.state = kind;
  $("status-text").textContent = text;
  $("progress").hidden = kind !== "loading";
}

export function showMessage(element, kind, text, details) {
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

export function robotFile() {
  const picked = state.robots.find((r) => r.name === $("robot").value);
  const text = $("yaml").value;
  return { yaml: text, file: picked && picked.yaml === text ? `${picked.name}.yaml` : "robot.yaml" };
}
