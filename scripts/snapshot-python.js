#!/usr/bin/env node
// Makes the browser page's Python state at build time: Pyodide's CPython (node_modules, the very
// runtime the page ships) imports SymPy and dhsym once, here, and its memory is saved, so that the
// page restores it instead of starting Python and importing (docs/web.md, "How it starts").
//
//     node scripts/snapshot-python.js STDLIB_ZIP SITE_ZIP MODULES OUT
//
// STDLIB_ZIP is Pyodide's standard library and SITE_ZIP the page's packages (SymPy, mpmath, PyYAML,
// dhsym), both byte-compiled; MODULES a file naming, one a line, the modules the page's outputs
// import on first use, imported here too. Nothing but imports runs: no result is worked out ahead.
// Writes to OUT:
//   python.snapshot.gzip    the memory without its pages of zeros, gzip-compressed (the page inflates
//                           it with DecompressionStream and puts the pages back in place)
//   python_stdlib.zip       the standard library's modules that were not imported
//   site-packages.zip       the same for the packages
// A module in the saved memory needs no file; what is left in the zips is imported from them on first
// use. The zips are swapped for the reduced ones before the memory is saved, so that the state's
// import caches describe the files the page writes at the same paths. Prints a JSON summary.
"use strict";
const fs = require("fs");
const path = require("path");
const zlib = require("zlib");
const { loadPyodide } = require("pyodide");

const STDLIB = "/lib/python314.zip"; // where Pyodide puts its standard library (CPython 3.14)
const SITE = "/lib/site-packages.zip"; // the page's packages, imported from the zip (zipimport)

const IMPORT = `
import gc, importlib, json, sys
sys.path.append(${JSON.stringify(SITE)})
# SymPy's import makes objects that live as long as the page: the collector is off while they are
# made, and they are frozen (never walked again), as the dhsym command does (dhsym/cli/__main__.py).
gc.disable()
from dhsym.web.app import handle
for name in json.loads(MODULES):
    importlib.import_module(name)
gc.freeze()
gc.enable()
`;

// The zip entries of the modules imported, by archive; then, once the reduced zips are in place,
// the import caches emptied (zipimport reads a zip's directory again on its next import).
const IMPORTED = `
import json, sys
def _imported(archive):
    prefix = archive + "/"
    origins = (getattr(getattr(m, "__spec__", None), "origin", None) or "" for m in list(sys.modules.values()))
    return sorted(origin[len(prefix):] for origin in origins if origin.startswith(prefix))
json.dumps({archive: _imported(archive) for archive in ${JSON.stringify([STDLIB, SITE])}})
`;
const FORGET_ZIPS = "import importlib, zipimport\nzipimport._zip_directory_cache.clear()\nimportlib.invalidate_caches()";

// The zip without the entries named in `drop`: the other entries' bytes as they are, a new central
// directory. Zips as Python's zipfile writes them to a file: no zip64, no data descriptors.
function withoutEntries(zip, drop) {
  const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  const end = zip.byteLength - 22;
  if (view.getUint32(end, true) !== 0x06054b50) throw new Error("not a zip without a comment");
  const count = view.getUint16(end + 10, true);
  let central = view.getUint32(end + 16, true);
  const locals = [], entries = [];
  let offset = 0;
  for (let i = 0; i < count; i++) {
    const nameLength = view.getUint16(central + 28, true);
    const size = 46 + nameLength + view.getUint16(central + 30, true) + view.getUint16(central + 32, true);
    const name = new TextDecoder().decode(zip.subarray(central + 46, central + 46 + nameLength));
    if (view.getUint16(central + 8, true) & 8) throw new Error(`${name}: data descriptors are not handled`);
    if (!drop.has(name)) {
      const start = view.getUint32(central + 42, true);
      const local = 30 + view.getUint16(start + 26, true) + view.getUint16(start + 28, true);
      const entry = zip.slice(central, central + size);
      new DataView(entry.buffer).setUint32(42, offset, true);
      locals.push(zip.subarray(start, start + local + view.getUint32(central + 20, true)));
      entries.push(entry);
      offset += locals.at(-1).length;
    }
    central += size;
  }
  const directory = entries.reduce((n, e) => n + e.length, 0);
  const tail = zip.slice(end, end + 22);
  const tailView = new DataView(tail.buffer);
  tailView.setUint16(8, entries.length, true);
  tailView.setUint16(10, entries.length, true);
  tailView.setUint32(12, directory, true);
  tailView.setUint32(16, offset, true);
  return Buffer.concat([...locals, ...entries, tail]);
}

// The memory without its pages of zeros (a third of it: the heap's untouched tops), which the page
// need not inflate: a header of little-endian 32-bit words [bytes in all, stretches, then the start
// and length of each stretch of non-zero pages], then those stretches' bytes one after another
// (web/worker.js puts them back in place in memory that starts as zeros).
const PAGE = 4096;

function withoutZeroPages(memory) {
  const stretches = [];
  for (let start = 0; start < memory.length; start += PAGE) {
    const page = memory.subarray(start, Math.min(start + PAGE, memory.length));
    if (page.every((byte) => byte === 0)) continue;
    const last = stretches.at(-1);
    if (last && last[0] + last[1] === start) last[1] += page.length;
    else stretches.push([start, page.length]);
  }
  const header = new Uint32Array([memory.length, stretches.length, ...stretches.flat()]);
  const parts = stretches.map(([start, length]) => memory.subarray(start, start + length));
  return Buffer.concat([Buffer.from(header.buffer), ...parts]);
}

// The randomness that the runtime asks for while it starts and imports (the C library's random
// state, the random module's seed) drawn from a fixed seed, and the wall clock (the files' times,
// which the import caches keep) stopped at a fixed date, so that each build saves the same memory.
const BUILD_DATE = Date.UTC(2020, 0, 1);

function reproducible() {
  let seed = 0x2545f491;
  const next = () => { // xorshift32
    seed ^= seed << 13;
    seed ^= seed >>> 17;
    seed ^= seed << 5;
    return seed >>> 0;
  };
  require("node:crypto").randomFillSync = (view) => {
    const bytes = new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
    for (let i = 0; i < bytes.length; i++) bytes[i] = next() & 0xff;
    return view;
  };
  Date.now = () => BUILD_DATE;
}

async function main() {
  const [stdlib, site, modules, out] = process.argv.slice(2);
  if (!out) {
    console.error("usage: node scripts/snapshot-python.js STDLIB_ZIP SITE_ZIP MODULES OUT");
    process.exit(2);
  }
  const indexURL = path.dirname(require.resolve("pyodide/package.json")) + path.sep;
  const siteBytes = fs.readFileSync(site);
  reproducible();
  const python = await loadPyodide({
    indexURL, stdLibURL: path.resolve(stdlib), _makeSnapshot: true, stdout: () => {}, stderr: (line) => console.error(line),
    env: { PYTHONHASHSEED: "0" }, // the same dicts and sets, laid out the same, in each build's saved memory
    fsInit: async (FS) => FS.writeFile(SITE, siteBytes),
  });
  const names = fs.readFileSync(modules, "utf8").split("\n").filter(Boolean);
  python.globals.set("MODULES", JSON.stringify(names));
  python.runPython(IMPORT);
  python.globals.delete("MODULES");
  const imported = JSON.parse(python.runPython(IMPORTED));
  python.globals.delete("_imported");
  const left = {};
  for (const [archive, target] of [[STDLIB, "python_stdlib.zip"], [SITE, "site-packages.zip"]]) {
    const reduced = withoutEntries(python.FS.readFile(archive), new Set(imported[archive]));
    python.FS.writeFile(archive, reduced);
    fs.writeFileSync(path.join(out, target), reduced);
    left[target] = imported[archive].length;
  }
  python.runPython(FORGET_ZIPS);
  const memory = python.makeMemorySnapshot();
  fs.writeFileSync(path.join(out, "python.snapshot.gzip"), zlib.gzipSync(withoutZeroPages(memory), { level: 9 }));
  const count = python.runPython("import sys\nlen(sys.modules)");
  console.log(JSON.stringify({ modules: count, "left out of the zips": left, memory: memory.length }));
}

main().catch((error) => {
  console.error(`snapshot-python: ${error.stack || error.message}`);
  process.exit(1);
});
