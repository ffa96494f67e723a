// dhsym's Python in a web worker (a module worker, as Pyodide asks), so that the page stays
// responsive while a result is worked out, and can stop a long one by ending the worker.
//
// Python does not start here as a program does: the build (scripts/snapshot-python.js) ran Pyodide's
// CPython once, imported SymPy and dhsym, and saved its memory in pyodide/python.snapshot; the worker
// restores that memory into the runtime, the modules not imported then are in pyodide/python_stdlib.zip
// and pyodide/site-packages.zip, written where the saved state expects them. Everything comes from
// this site's pyodide/ folder, fetched at once.
//
// Messages in:  {id, request}            a request for dhsym.web.app.handle (JSON text)
// Messages out: {kind: "progress", loaded, total}  bytes so far, for the progress bar
//               {kind: "stage", text}     what the runtime is doing once its bytes are in
//               {kind: "ready", seconds, timings, versions}  Python is up with dhsym imported
//               {kind: "failed", message} the runtime could not be loaded
//               {kind: "answer", id, answer, seconds}
const SITE = "/lib/site-packages.zip"; // where the saved state imports the page's packages from
const HEADER_WORDS = 4; // a snapshot starts with [magic, bytes before the memory, ...] (Pyodide's format)
const RUNTIME = new URL("pyodide/pyodide.asm.wasm", self.location.href).href; // what Pyodide would fetch

let python = null;
const started = performance.now();
const marks = {}; // seconds since the worker started, for benchmarks/web_speed.py
const mark = (name) => { marks[name] = (performance.now() - started) / 1000; };

// The bytes of every file fetched, counted for the progress bar as they arrive (from a copy of each
// response, the response itself goes on untouched); build.json says how many to expect.
function countingFetch(realFetch, onBytes) {
  return async (input, init) => {
    const response = await realFetch(input, init);
    if (response.ok && response.body) {
      const reader = response.clone().body.getReader();
      (async () => {
        for (let read = await reader.read(); !read.done; read = await reader.read()) onBytes(read.value.byteLength);
      })().catch(() => {});
    }
    return response;
  };
}

// A gzip-compressed file of this site's pyodide/ folder, inflated as it arrives (the browser's own
// DecompressionStream): a stream of its bytes.
async function inflating(name) {
  const response = await fetch(`pyodide/${name}.gzip`);
  if (!response.ok) throw new Error(`pyodide/${name}.gzip: ${response.status} ${response.statusText}`);
  return response.body.pipeThrough(new DecompressionStream("gzip"));
}

async function inflated(name) {
  const bytes = await new Response(await inflating(name)).arrayBuffer();
  mark(`${name} inflated`);
  return bytes;
}

// The saved memory, as the build wrote it (scripts/snapshot-python.js): its non-zero stretches, put
// in place as they are inflated, in memory that starts as zeros. First a header of little-endian
// 32-bit words: [bytes in all, stretches, then the start and length of each stretch].
async function savedMemory() {
  const reader = (await inflating("python.snapshot")).getReader();
  let head = new Uint8Array(0);
  let memory = null;
  let stretches = [];
  let [stretch, done] = [0, 0]; // the stretch being filled, and its bytes filled so far
  for (let read = await reader.read(); !read.done; read = await reader.read()) {
    let chunk = read.value;
    if (!memory) {
      head = joined(head, chunk);
      const words = head.length >= 8 ? 2 + 2 * wordAt(head, 1) : Infinity;
      if (head.length < 4 * words) continue;
      memory = new Uint8Array(wordAt(head, 0));
      stretches = Array.from({ length: words - 2 }, (_, i) => wordAt(head, 2 + i));
      chunk = head.subarray(4 * words);
    }
    while (chunk.length) {
      if (stretch === stretches.length / 2) throw new Error(CUT);
      const [start, length] = [stretches[2 * stretch], stretches[2 * stretch + 1]];
      const taken = Math.min(length - done, chunk.length);
      memory.set(chunk.subarray(0, taken), start + done);
      chunk = chunk.subarray(taken);
      done += taken;
      if (done === length) [stretch, done] = [stretch + 1, 0];
    }
  }
  if (!memory || stretch !== stretches.length / 2) throw new Error(CUT);
  mark("python.snapshot inflated");
  return memory;
}

const CUT = "pyodide/python.snapshot.gzip is not the saved memory this page was built with; build the page again";
const wordAt = (bytes, index) => new DataView(bytes.buffer, bytes.byteOffset).getUint32(4 * index, true);

function joined(first, second) {
  const both = new Uint8Array(first.length + second.length);
  both.set(first);
  both.set(second, first.length);
  return both;
}

// Pyodide's runtime: the WebAssembly compiled as it arrives, and its JavaScript as a module.
async function compiledRuntime() {
  const headers = { "Content-Type": "application/wasm" };
  const compiled = await WebAssembly.compileStreaming(new Response(await inflating("pyodide.asm.wasm"), { headers }));
  mark("runtime compiled");
  return compiled;
}

async function runtimeScript() {
  const source = new Blob([await inflated("pyodide.asm.mjs")], { type: "text/javascript" });
  return (await import(URL.createObjectURL(source))).default;
}

async function start() {
  const realFetch = self.fetch.bind(self);
  let loaded = 0;
  let total = 0;
  self.fetch = countingFetch(realFetch, (bytes) => {
    loaded += bytes;
    if (total) postMessage({ kind: "progress", loaded: Math.min(loaded, total), total });
  });
  // Everything at once: the state, the runtime (compiled as it arrives), the packages, and Pyodide's
  // JavaScript, which Python's start needs only after them.
  const manifest = realFetch("build.json").then((r) => r.json());
  const state = savedMemory();
  const site = fetch("pyodide/site-packages.zip").then((r) => r.arrayBuffer());
  const restore = useCompiledRuntime(compiledRuntime(), prefetched(["python_stdlib.zip", "pyodide-lock.json"]));
  const [{ loadPyodide }, createPyodideModule] = await Promise.all([import("./pyodide/pyodide.mjs"), runtimeScript()]);
  total = Object.values((await manifest).files).reduce((a, b) => a + b, 0);
  let memory = 0;
  python = await loadPyodide({
    indexURL: new URL("pyodide/", self.location.href).href,
    _loadSnapshot: state.then((bytes) => {
      memory = bytes.length - new Uint32Array(bytes.buffer, 0, HEADER_WORDS)[1];
      postMessage({ kind: "stage", text: "Starting Python" });
      return bytes;
    }),
    // The runtime's memory made as large as the saved one before it is copied in.
    createPyodideModule: async (settings) => {
      const module = await createPyodideModule(settings);
      module.growMemory(memory);
      mark("runtime made");
      return module;
    },
    fsInit: async (FS) => FS.writeFile(SITE, new Uint8Array(await site)),
    stdout: () => {},
    stderr: (line) => console.warn(line),
  });
  restore();
  self.fetch = realFetch;
  mark("python ready");
  postMessage({ kind: "ready", seconds: marks["python ready"], timings: marks, versions: await manifest });
}

// What Pyodide itself fetches once it starts (its standard library and lock file), asked for now:
// {URL: response}.
function prefetched(names) {
  return Object.fromEntries(names.map((name) => {
    const url = new URL(`pyodide/${name}`, self.location.href).href;
    return [url, fetch(url)];
  }));
}

// Pyodide fetches and compiles its runtime when it makes it, once the state is in; here it was
// compiled while the state downloaded, and Pyodide is handed that instead (its fetch is not made),
// and the files it fetches are handed over from `early`, fetched already. Gives the function that
// puts fetch and WebAssembly back.
function useCompiledRuntime(runtime, early) {
  const [fetching, instantiateStreaming] = [self.fetch, WebAssembly.instantiateStreaming];
  self.fetch = (input, init) => {
    const url = String(input);
    if (url === RUNTIME) return Promise.resolve(new Response(null));
    const response = early[url];
    delete early[url];
    return response || fetching(input, init);
  };
  WebAssembly.instantiateStreaming = async (source, imports) => {
    await source;
    const module = await runtime;
    return { module, instance: await WebAssembly.instantiate(module, imports) };
  };
  return () => {
    self.fetch = fetching;
    WebAssembly.instantiateStreaming = instantiateStreaming;
  };
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
  if (!marks["first answer"]) mark("first answer");
  postMessage({ kind: "answer", id, answer, seconds: (performance.now() - began) / 1000 });
};
