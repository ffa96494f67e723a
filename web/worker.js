// dhsym's Python in a web worker (a module worker, as Pyodide asks): Pyodide's runtime and the page's four wheels (dhsym, SymPy, mpmath,
// PyYAML) from this site's pyodide/ folder, listed in pyodide/pyodide-lock.json. The page stays
// responsive while a result is worked out, and can stop a long one by ending the worker.
//
// Messages in:  {id, request}            a request for dhsym.web.app.handle (JSON text)
// Messages out: {kind: "progress", loaded, total}  bytes so far, for the progress bar
//               {kind: "stage", text}     what the runtime is doing once its bytes are in
//               {kind: "ready", seconds}  Python is up and dhsym imported
//               {kind: "failed", message} the runtime could not be loaded
//               {kind: "answer", id, answer, seconds}
import { loadPyodide } from "./pyodide/pyodide.mjs";

let python = null;

// Counts the bytes of every file Pyodide fetches, for the page's progress bar; build.json says how
// many to expect. Nothing is changed in what is fetched.
function countingFetch(realFetch, onBytes, onDone) {
  return async (input, init) => {
    const response = await realFetch(input, init);
    if (!response.body) return response;
    const reader = response.body.getReader();
    const stream = new ReadableStream({
      async pull(controller) {
        const { done, value } = await reader.read();
        if (done) {
          controller.close();
          onDone(String(input));
          return;
        }
        onBytes(value.byteLength);
        controller.enqueue(value);
      },
      cancel(reason) {
        return reader.cancel(reason);
      },
    });
    return new Response(stream, { status: response.status, statusText: response.statusText, headers: response.headers });
  };
}

async function start() {
  const started = performance.now();
  const manifest = await (await fetch("build.json")).json();
  const total = Object.values(manifest.files).reduce((a, b) => a + b, 0);
  let loaded = 0;
  const report = (bytes) => {
    loaded = Math.min(total, loaded + bytes);
    postMessage({ kind: "progress", loaded, total });
  };
  const realFetch = self.fetch.bind(self);
  const stage = (text) => postMessage({ kind: "stage", text });
  self.fetch = countingFetch(realFetch, report, (url) => {
    if (url.endsWith(".wasm")) stage("Starting Python");
  });
  const indexURL = new URL("pyodide/", self.location.href).href;
  // The wheels download while the runtime starts (Pyodide's `packages`).
  python = await loadPyodide({ indexURL, packages: ["dhsym"], stdout: () => {}, stderr: (line) => console.warn(line) });
  report(manifest.files["pyodide/pyodide.asm.mjs"] || 0); // imported as a module, not fetched
  self.fetch = realFetch;
  stage("Importing SymPy and dhsym");
  const installed = performance.now();
  // SymPy's import makes objects that live as long as the page: the collector is off while they are
  // made, and they are frozen (never walked again), as the dhsym command does (dhsym/cli/__main__.py).
  python.runPython("import gc\ngc.disable()\nfrom dhsym.web.app import handle\ngc.freeze()\ngc.enable()");
  const seconds = { load: (installed - started) / 1000, imports: (performance.now() - installed) / 1000 };
  postMessage({ kind: "ready", seconds: (performance.now() - started) / 1000, timings: seconds, versions: manifest });
}

const starting = start().catch((error) => {
  postMessage({ kind: "failed", message: String(error && error.message ? error.message : error) });
  throw error;
});

self.onmessage = async (event) => {
  const { id, request } = event.data;
  await starting;
  const began = performance.now();
  let answer;
  try {
    const handle = python.globals.get("handle");
    answer = handle(request);
    handle.destroy();
  } catch (error) { // the runtime itself failed (out of memory, say): handle never raises
    answer = JSON.stringify({ state: "error", internal: true, traceback: String(error && error.stack),
                              message: `Python stopped working in this page (${String(error && error.message).split("\n")[0]}); reload the page` });
  }
  postMessage({ kind: "answer", id, answer, seconds: (performance.now() - began) / 1000 });
};
