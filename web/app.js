// The page: a robot picker and a YAML editor on the left, the drawing of the arm under them, the
// results on the right, typeset by MathJax. dhsym itself runs in worker.js (python.js talks to it);
// every request is answered by dhsym.web.app.handle, and every answer is JSON.
//
// Deep links: index.html?robot=NAME&show=table|links|fk|jacobian|ik (with &from=I&to=J for fk,
// &frame=K&point=P for the Jacobian), and #yaml=... (a robot file, URL-encoded) for an arm of one's
// own. The result stands in #result, whose data-state is "loading", "working", "ready" or "error".
import { showProblem, fillGutter, markLine } from "./editor.js";
import { refreshDrawing } from "./drawing.js";
import { $, robotFile, state } from "./page.js";
import { ask, failed, startWorker, stopWorker } from "./python.js";
import { chosenFrames, freeVariables, refresh, warmUpMath } from "./results.js";

const SHOWS = ["table", "links", "fk", "jacobian", "ik"];

const SHOW_FRAMES = { fk: ["from", "to"], jacobian: ["frame", "point"] }; // the frames each output takes

const DEFAULT_ROBOT = "puma560";

const EDIT_PAUSE_MS = 500; // typing pauses this long before the result is worked out again

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

function selectTab(show) {
  state.show = SHOWS.includes(show) ? show : "fk";
  for (const tab of document.querySelectorAll("#tabs button")) {
    tab.setAttribute("aria-selected", String(tab.dataset.show === state.show));
  }
  document.body.dataset.show = state.show;
}

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

async function main() {
  startWorker();
  if (state.failed) return;
  window.addEventListener("load", warmUpMath);
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
