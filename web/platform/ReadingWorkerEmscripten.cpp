// The reading worker in the browser: a Web Worker running essi_reader.js or essi_reader_mt.js (web/worker/), started
// on a cross-origin isolated page once the page's own warm-up is done (prepare), else by the first tape handed to
// it; it warms its code up on built-in tapes while it waits ({warmUp}). The page posts it a job (the
// request's header and a copy of the tape's bytes, both transferred) and it posts back ReadingJob.hpp's messages,
// which land here (essi_reading_buffer, then essi_reading_received) for WorkerLoader to pick up in the next frame. A
// job handed over while another runs ends the worker and starts a new one (a job runs to its end once begun). The
// end of a job on a large tape does too, which gives its memory back; that new worker warms its code up on built-in
// tapes while it waits ({warmUp}). A worker that cannot start or fails sends its job a Failed message: the page
// reads the tape itself.
#include <emscripten.h>

#include <deque>
#include <utility>

#include "app/ReadingJob.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

namespace {

class WebReadingWorker final : public ReadingWorker {
public:
    void prepare() override;
    void post(std::uint32_t job, std::string_view header, std::string_view bytes) override;
    void analyse_plan(std::uint32_t job) override;
    std::optional<std::string> receive(std::uint32_t job) override;
    void cancel(std::uint32_t job) override;

    // A message of `job` is being written (essi_reading_buffer), then is complete (essi_reading_received).
    char* begin_message(std::uint32_t job, std::size_t size) {
        incoming_job_ = job;
        incoming_.assign(size, '\0');
        return incoming_.data();
    }
    void end_message() { messages_.emplace_back(incoming_job_, std::move(incoming_)); }

private:
    std::deque<std::pair<std::uint32_t, std::string>> messages_;
    std::uint32_t incoming_job_ = 0;
    std::string incoming_;
};

WebReadingWorker g_worker;

// clang-format off
/* On unless the page's address has ?worker=0 (the page then reads every tape itself, as it does without Worker). */
EM_JS(int, essi_reading_supported, (), {
    const off = new URLSearchParams(location.search).get('worker') === '0';
    return !off && typeof Worker !== 'undefined' ? 1 : 0;
});

// The page's side of the worker: Module.essikitReading, made once. A worker started is told to warm up ({warmUp}):
// a job that comes first stops that. A cross-origin isolated page (SharedArrayBuffer: essi serve's COOP/COEP) starts
// the program built with threads, which checks a big tape on two (essi/pipelined_check.hpp);
// any other page the one-thread program. `script` says which.
EM_JS(void, essi_reading_setup, (), {
    if (Module.essikitReading) return;
    Module.essikitReading = {
        worker: null, job: 0, bytes: 0,
        script: self.crossOriginIsolated ? 'essi_reader_mt.js' : 'essi_reader.js',
        start() {
            this.worker = new Worker(this.script);
            this.worker.onmessage = (e) => this.deliver(e.data.job, new Uint8Array(e.data.data));
            this.worker.onerror = (e) => {
                e.preventDefault();
                const text = 'e' + 'the reading worker failed: ' + (e.message || 'its script could not be loaded');
                if (this.job) this.deliver(this.job, new TextEncoder().encode(text));
                this.stop();
            };
            this.worker.postMessage({warmUp: true});
        },
        stop() {
            if (this.worker) this.worker.terminate();
            this.worker = null;
            this.job = 0;
        },
        deliver(job, data) {
            const ptr = Module._essi_reading_buffer(job, data.length);
            Module.HEAPU8.set(data, ptr);
            Module._essi_reading_received();
            const last = data[0] === 102 || data[0] === 101; /* 'f', 'e': the job's last message */
            if (last && job === this.job) {
                this.job = 0;
                if (this.bytes >= 32 * 1024 * 1024) { this.stop(); this.start(); } /* (its memory back) */
            }
        },
    };
});

/* Only on a cross-origin isolated page (essi serve's: a local server, its scripts gzip-encoded): elsewhere the 0.8 MB
   of the worker's program would join the page's first load for tapes most visits never drop. */
EM_JS(void, essi_reading_prepare, (), {
    const r = Module.essikitReading;
    if (!r.worker && self.crossOriginIsolated) r.start();
});

/* (the worker's script beside the page; a job's buffers are transferred, not copied again) */
EM_JS(void, essi_reading_post, (std::uint32_t job, const char* header, std::size_t header_len, const char* bytes,
                                std::size_t bytes_len), {
    const r = Module.essikitReading;
    if (r.job) r.stop();
    if (!r.worker) r.start();
    r.job = job;
    r.bytes = bytes_len;
    const h = HEAPU8.slice(header, header + header_len).buffer;
    const b = HEAPU8.slice(bytes, bytes + bytes_len).buffer;
    r.worker.postMessage({job: job, header: h, bytes: b}, [h, b]);
});

EM_JS(void, essi_reading_analyse_plan, (std::uint32_t job), {
    const r = Module.essikitReading;
    if (r && r.job === job) r.worker.postMessage({job: job, plan: true});
});

EM_JS(void, essi_reading_cancel, (std::uint32_t job), {
    const r = Module.essikitReading;
    if (r && r.job === job) r.stop();
});
// clang-format on

void WebReadingWorker::prepare() {
    essi_reading_setup();
    essi_reading_prepare();
}

void WebReadingWorker::post(std::uint32_t job, std::string_view header, std::string_view bytes) {
    essi_reading_setup();
    essi_reading_post(job, header.data(), header.size(), bytes.data(), bytes.size());
}

void WebReadingWorker::analyse_plan(std::uint32_t job) { essi_reading_analyse_plan(job); }

std::optional<std::string> WebReadingWorker::receive(std::uint32_t job) {
    while (!messages_.empty()) {
        auto [from, message] = std::move(messages_.front());
        messages_.pop_front();
        if (from == job) return std::move(message);  // (an older job's messages are dropped)
    }
    return std::nullopt;
}

void WebReadingWorker::cancel(std::uint32_t job) {
    std::erase_if(messages_, [job](const auto& m) { return m.first == job; });  // (a document may be among them)
    essi_reading_cancel(job);
}

}  // namespace

ReadingWorker* Platform::reading_worker() { return essi_reading_supported() != 0 ? &g_worker : nullptr; }

}  // namespace essi::viewer::platform

extern "C" {
// Room for a message of `job` of `size` bytes, which the page's script writes there.
EMSCRIPTEN_KEEPALIVE char* essi_reading_buffer(std::uint32_t job, std::size_t size) {
    return essi::viewer::platform::g_worker.begin_message(job, size);
}
// The message written is complete.
EMSCRIPTEN_KEEPALIVE void essi_reading_received() { essi::viewer::platform::g_worker.end_message(); }
}
