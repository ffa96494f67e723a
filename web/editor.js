// The robot file's editor: line numbers, the error's line marked, and the messages under it.
import { $ } from "./page.js";

// A band behind the line of the robot file's error, under the text, moving with it as it scrolls.
export function markLine(line) {
  const band = $("error-band");
  band.hidden = !line;
  if (!line) return;
  const style = getComputedStyle($("yaml"));
  const height = parseFloat(style.lineHeight);
  band.style.height = `${height}px`;
  band.style.top = `${parseFloat(style.paddingTop) + (line - 1) * height - $("yaml").scrollTop}px`;
  band.dataset.line = line;
}

export function fillGutter(errorLine) {
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

export function showProblem(answer) {
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
