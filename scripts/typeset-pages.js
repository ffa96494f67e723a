#!/usr/bin/env node
// Typesets the TeX of exported notebook pages in place, as SVG, so that a page shows its
// formulas with no network and no script: a lecture hall without internet, an exam machine,
// a course site that blocks third-party scripts. MathJax 3 (the version JupyterLab 4 bundles)
// comes from node_modules, installed from package-lock.json by scripts/ensure-node-packages.sh.
//
//     node scripts/typeset-pages.js build/notebooks/*.html
//
// Delimiters are those of Jupyter: $...$ and \(...\) inline, $$...$$ and \[...\] displayed,
// \begin{...} environments; <pre> and <code> are left alone. A TeX error stops the export with
// the page and the message, rather than leaving red source in a page.
"use strict";
const fs = require("fs");
const path = require("path");
const { mathjax } = require("mathjax-full/js/mathjax.js");
const { TeX } = require("mathjax-full/js/input/tex.js");
const { SVG } = require("mathjax-full/js/output/svg.js");
const { liteAdaptor } = require("mathjax-full/js/adaptors/liteAdaptor.js");
const { RegisterHTMLHandler } = require("mathjax-full/js/handlers/html.js");
const { AssistiveMmlHandler } = require("mathjax-full/js/a11y/assistive-mml.js");
const { AllPackages } = require("mathjax-full/js/input/tex/AllPackages.js");

const adaptor = liteAdaptor();
// Screen readers get MathML beside each picture.
AssistiveMmlHandler(RegisterHTMLHandler(adaptor));

function typeset(file) {
  const errors = [];
  const tex = new TeX({
    packages: AllPackages.filter((name) => name !== "bussproofs"),
    inlineMath: [["$", "$"], ["\\(", "\\)"]],
    processEscapes: true,
    formatError(jax, error) {
      errors.push(error.message);
      return jax.formatError(error);
    },
  });
  // One copy of each glyph per page, referenced by every formula.
  const svg = new SVG({ fontCache: "global" });
  const page = mathjax.document(fs.readFileSync(file, "utf8"), { InputJax: tex, OutputJax: svg });
  page.render();
  const items = Array.from(page.math);
  // The source stays with its picture, so that a test or a reader can tell which formula is which.
  for (const item of items) adaptor.setAttribute(item.typesetRoot, "data-tex", item.math);
  const count = items.length;
  if (count === 0) adaptor.remove(svg.svgStyles);
  const html = adaptor.doctype(page.document) + "\n" + adaptor.outerHTML(adaptor.root(page.document));
  const temporary = path.join(path.dirname(file), `.${path.basename(file)}.typesetting`);
  fs.writeFileSync(temporary, html);
  fs.renameSync(temporary, file);  // a page is either the old one or the typeset one, never half
  return { count, errors };
}

let failed = false;
for (const file of process.argv.slice(2)) {
  const { count, errors } = typeset(file);
  for (const message of errors) console.error(`typeset-pages: ${file}: TeX error: ${message}`);
  failed = failed || errors.length > 0;
  console.log(`typeset-pages: ${file}: ${count} formulas`);
}
process.exit(failed ? 1 : 0);
