// The result: asked for at the line width of the column, then typeset piece by piece with MathJax.
import { showProblem } from "./editor.js";
import { refreshDrawing } from "./drawing.js";
import { $, mark, robotFile, showMessage, state } from "./page.js";
import { ask } from "./python.js";

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

export async function refresh() {
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
  mark("first result typeset");
}

// MathJax, with its stylesheet for the SVG it makes (typeset piece by piece, the page adds it itself).
let mathStyles = null;

// MathJax's first formulas set up its parser, its fonts and the code of each construct, and its code
// runs faster once the browser has compiled it for speed (after a few runs): done while Python loads,
// with formulas like the results' (a matrix, sums of products in brackets, definitions), each in a
// task of its own, and no more once the first answer is in.
const WARM_UP = [
  "{}^{0}T_{1} = \\begin{bmatrix} c_{1} & -s_{1} & 0 & a_{1} c_{1} \\\\ s_{1} & c_{1} & 0 & a_{1} s_{1} \\\\ 0 & 0 & 0 & 1 \\end{bmatrix}",
  "\\begin{align*} r_{11} &= c_{1}[c_{23}(c_{4} c_{5} c_{6} - s_{4} s_{6}) - s_{23} s_{5} c_{6}] + s_{1}(c_{4} s_{6}) \\\\ " +
    "p_{x} &= -a_{2} c_{1} c_{2} + d_{4} s_{23} \\end{align*}",
  "\\begin{align*} c_{1} &= \\cos{\\theta_{1}} & s_{23} &= \\sin(\\theta_{2} + \\theta_{3}) \\end{align*}",
];
const WARM_UP_ROUNDS = 3;

export async function warmUpMath() {
  await mathReady();
  mathEm();
  for (let round = 0; round < WARM_UP_ROUNDS; round++) {
    for (const tex of WARM_UP) {
      if (state.latex) return; // a result is being typeset: the warm-up is over
      MathJax.tex2svg(tex, { display: true });
      await new Promise((resolve) => setTimeout(resolve));
    }
  }
}

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

// The frames of ⁱTⱼ for the forward kinematics: what the reader chose, else (null) the whole chain.
export function chosenFrames() {
  if (!state.framesChosen) return {};
  if (state.show === "fk") return { from: $("from").value || null, to: $("to").value || null };
  if (state.show === "jacobian") return { frame: $("frame").value || null, point: $("point").value || null };
  return {};
}

export function freeVariables() {
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
