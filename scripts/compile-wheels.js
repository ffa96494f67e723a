#!/usr/bin/env node
// Byte-compiles the Python files under a folder with the very interpreter the browser page runs:
// Pyodide's own CPython, from node_modules, with the folder mounted into its file system. A .pyc is
// valid only for the CPython version that wrote it, so the page's Python must write them; the
// browser then imports them without compiling (half the page's cold start, see docs/web.md).
//
//     node scripts/compile-wheels.js build/web-cache/unpacked
//
// Each foo.py gets a foo.pyc beside it (the sourceless layout, which imports without its .py); the
// build (scripts/build_web.py) then drops the .py files and packs the wheels again. Docstrings are
// left out (as `python -OO` does; asserts stay): they are a third of SymPy's bytes, and nothing the
// page runs reads them (dhsym's outputs are the same under -OO). Nor are the columns of each line
// (PYTHONNODEBUGRANGES, as `python -X no_debug_ranges` does): a traceback still names the file and
// line, without the ^^^ under the failing expression, and the code is a tenth smaller, in the files
// and in the page's memory. The header holds a hash instead of
// a time stamp, so that the same sources give the same bytes. Prints the Python version and the
// count of files compiled.
"use strict";
const path = require("path");
const { loadPyodide } = require("pyodide");

const COMPILE = `
import ast, importlib.util, pathlib, sys
from importlib._bootstrap_external import _code_to_hash_pyc

def without_docstrings(tree):
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
                node.body[:1] = [] if len(node.body) > 1 else [ast.copy_location(ast.Pass(), first)]
    return tree

KEEP_DOCSTRINGS = ("_pyodide", "pyodide")  # Pyodide's own packages hand theirs to the JavaScript side
root = pathlib.Path("/tree")
count = 0
for source in sorted(root.rglob("*.py")):
    data = source.read_bytes()
    shown = "/".join(source.relative_to(root).parts[1:])  # the path a traceback names, e.g. sympy/core/basic.py
    tree = ast.parse(data, shown)
    if shown.split("/")[0] not in KEEP_DOCSTRINGS:
        tree = without_docstrings(tree)
    code = compile(tree, shown, "exec", dont_inherit=True)
    pathlib.Path(str(source) + "c").write_bytes(_code_to_hash_pyc(code, importlib.util.source_hash(data), False))
    count += 1
if any(column is not None for _, _, column, _ in compile("a = b", "-", "exec").co_positions()):
    raise SystemExit("columns are still compiled in: PYTHONNODEBUGRANGES was not read")
f"{sys.version.split()[0]} {count}"
`;

async function main() {
  const folder = process.argv[2];
  if (!folder) {
    console.error("usage: node scripts/compile-wheels.js FOLDER");
    process.exit(2);
  }
  const indexURL = path.dirname(require.resolve("pyodide/package.json")) + path.sep;
  const pyodide = await loadPyodide({ indexURL, env: { PYTHONNODEBUGRANGES: "1" }, stdout: () => {},
                                      stderr: (line) => console.error(line) });
  pyodide.FS.mkdir("/tree");
  pyodide.FS.mount(pyodide.FS.filesystems.NODEFS, { root: path.resolve(folder) }, "/tree");
  console.log(pyodide.runPython(COMPILE));
}

main().catch((error) => {
  console.error(`compile-wheels: ${error.message}`);
  process.exit(1);
});
