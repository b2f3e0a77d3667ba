// The reading worker's side of the messages (before Emscripten's code in essi_reader.js): each message from the
// page is a job { job, header, bytes } (ArrayBuffers), run once the program has started, one after another.
var essiReaderJobs = [];
var essiReaderStarted = false;

function essiReaderRun(m) {
  const header = new Uint8Array(m.header);
  const bytes = new Uint8Array(m.bytes);
  const at = Module._essi_reader_buffer(bytes.length);
  Module.HEAPU8.set(bytes, at);
  const h = Module._malloc(Math.max(header.length, 1));
  Module.HEAPU8.set(header, h);
  try {
    Module._essi_reader_run(m.job, h, header.length);
  } finally {
    Module._free(h);
  }
}

Module['onRuntimeInitialized'] = function () {
  essiReaderStarted = true;
  for (const m of essiReaderJobs.splice(0)) essiReaderRun(m);
};

self.onmessage = function (e) {
  if (essiReaderStarted) essiReaderRun(e.data);
  else essiReaderJobs.push(e.data);
};
