// The reading worker's side of the messages (before Emscripten's code in essi_reader.js and essi_reader_mt.js): the
// page posts a job { job, header, bytes } (ArrayBuffers) for each tape, run once the program has started, one after
// another, up to its document; { job, plan: true } when the page wants the job's cut plan, analysed in slices of
// kPlanSliceMs (a job's messages are not held up meanwhile: each slice is a task of its own); and { warmUp: true } once, before the first: the warm-up's tapes are then read in slices of
// kWarmUpSliceMs until done or until a job comes. In essi_reader_mt.js's reading thread (a worker of its own that
// loads this script too, Module.ENVIRONMENT_IS_PTHREAD) none of this applies: Emscripten's messages are its own.
// The heap is HEAPU8, not Module.HEAPU8: in essi_reader_mt.js Emscripten renews that view when the reading thread
// has grown the memory (a growable shared heap).
var essiReaderJobs = [];
var essiReaderStarted = false;
var essiReaderWarming = false;
var kWarmUpSliceMs = 20;
var kPlanSliceMs = 50;

function essiReaderRun(m) {
  essiReaderWarming = false;  // (a tape of the page's own: warm enough now)
  const header = new Uint8Array(m.header);
  const bytes = new Uint8Array(m.bytes);
  const at = Module._essi_reader_buffer(bytes.length);
  HEAPU8.set(bytes, at);
  const h = Module._malloc(Math.max(header.length, 1));
  HEAPU8.set(header, h);
  try {
    Module._essi_reader_run(m.job, h, header.length);
  } finally {
    Module._free(h);
  }
}

// The next slice as a task of its own (the page's messages are taken between two), posted to a MessageChannel: a
// chain of setTimeout(0) is held back 4 ms a call after the fifth.
var essiReaderSlices = null;
function essiReaderNextSlice(f) {
  if (!essiReaderSlices) {
    essiReaderSlices = {channel: new MessageChannel(), queue: []};
    essiReaderSlices.channel.port1.onmessage = () => essiReaderSlices.queue.shift()();
  }
  essiReaderSlices.queue.push(f);
  essiReaderSlices.channel.port2.postMessage(0);
}

function essiReaderPlan(job) {
  if (Module._essi_reader_plan(job, kPlanSliceMs)) essiReaderNextSlice(() => essiReaderPlan(job));
}

function essiReaderWarmUp() {
  if (!essiReaderWarming) return;
  if (Module._essi_reader_warm_up(kWarmUpSliceMs)) essiReaderNextSlice(essiReaderWarmUp);
  else essiReaderWarming = false;
}

if (!Module['ENVIRONMENT_IS_PTHREAD']) {
  Module['onRuntimeInitialized'] = function () {
    essiReaderStarted = true;
    for (const m of essiReaderJobs.splice(0)) essiReaderRun(m);
    essiReaderWarmUp();
  };

  self.onmessage = function (e) {
    if (e.data.warmUp) {
      essiReaderWarming = true;
      if (essiReaderStarted) essiReaderWarmUp();
    } else if (e.data.plan) {
      essiReaderPlan(e.data.job);  // (a job's plan is asked for after its document: the program has started)
    } else if (essiReaderStarted) {
      essiReaderRun(e.data);
    } else {
      essiReaderJobs.push(e.data);
    }
  };
}
