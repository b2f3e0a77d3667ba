// The reading worker's program (essi_reader.js and .wasm, in a Web Worker the page starts:
// platform/ReadingWorkerEmscripten.cpp). Each job the page posts is read and checked by ReadingJob.hpp's ReadingJob,
// up to its document; its cut plan once the page asks for it, in slices; their messages go back to the page as they
// are made (reader_worker.pre.js has the worker's side of the messages).
#include <emscripten.h>

#include <cstdint>
#include <iterator>
#include <memory>
#include <string>

#include "app/ReadingJob.hpp"
#include "essi/dialect.hpp"
#include "essi_warm_up_tapes.hpp"

namespace {

std::string g_bytes;  // the tape of the next job (essi_reader_buffer)
// The job read, its plan still to analyse, and its number.
std::unique_ptr<essi::viewer::ReadingJob> g_job;
std::uint32_t g_job_number = 0;

// The warm-up: the page's warm-up tapes (web/CMakeLists.txt) read through the job, messages dropped, until as many
// bytes as the page's own warm-up (WarmUp::kBytes) were read: meanwhile the browser compiles the hot functions
// at its top tier, so that the first tape does not run in baseline code.
constexpr std::size_t kWarmUpBytes = 200000;
std::size_t g_warm_up_bytes = 0;
std::size_t g_warm_up_tapes = 0;

// clang-format off
EM_JS(void, essi_reader_post, (std::uint32_t job, char kind, const char* body, std::size_t len), {
    const data = new Uint8Array(len + 1);
    data[0] = kind;
    data.set(HEAPU8.subarray(body, body + len), 1);
    postMessage({job: job, data: data.buffer}, [data.buffer]);
});
// clang-format on

essi::viewer::PostReadingMessage post_to(std::uint32_t job) {
    return [job](essi::viewer::ReadingMessage kind, std::string_view body) {
        essi_reader_post(job, static_cast<char>(kind), body.data(), body.size());
    };
}

}  // namespace

extern "C" {

// Room for the next job's tape of `size` bytes, which the worker's script writes there.
EMSCRIPTEN_KEEPALIVE char* essi_reader_buffer(std::size_t size) {
    g_bytes.assign(size, '\0');
    return g_bytes.data();
}

// Warm-up tapes for about `budget_ms`; 1 while there are more to read.
EMSCRIPTEN_KEEPALIVE int essi_reader_warm_up(double budget_ms) {
    namespace tapes = essi::warm_up_tapes;
    const double until = emscripten_get_now() + budget_ms;
    while (g_warm_up_bytes < kWarmUpBytes && emscripten_get_now() < until) {
        const tapes::EmbeddedFile& file = tapes::kFiles[g_warm_up_tapes++ % std::size(tapes::kFiles)];
        std::string bytes = file.text;
        g_warm_up_bytes += bytes.size();
        essi::TapeSetup setup = essi::setup_tape(bytes, std::nullopt, std::nullopt);
        essi::viewer::read_for_page(file.name, std::move(bytes), std::move(setup),
                                    [](essi::viewer::ReadingMessage, std::string_view) {});
    }
    return g_warm_up_bytes < kWarmUpBytes ? 1 : 0;
}

// Reads and checks the tape put in essi_reader_buffer as the request `header` says, up to its document.
EMSCRIPTEN_KEEPALIVE void essi_reader_run(std::uint32_t job, const char* header, std::size_t header_len) {
    g_job = std::make_unique<essi::viewer::ReadingJob>();
    g_job_number = job;
    if (!g_job->read(std::string_view(header, header_len), std::move(g_bytes), post_to(job))) g_job.reset();
    g_bytes = std::string();
}

// The cut plan of job `job` for about `budget_ms` (once the page asked); 1 while there is more.
EMSCRIPTEN_KEEPALIVE int essi_reader_plan(std::uint32_t job, double budget_ms) {
    if (!g_job || job != g_job_number) return 0;
    if (!g_job->analyse_plan(budget_ms, post_to(job))) return 1;
    g_job.reset();
    return 0;
}

}  // extern "C"

int main() { return 0; }
