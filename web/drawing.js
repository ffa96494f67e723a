// The drawing of the arm (dhsym's own SVG) and a slider for each joint variable.
import { $, robotFile, showMessage, state } from "./page.js";
import { ask } from "./python.js";

export async function refreshDrawing() {
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
