// The reading worker's program (essi_reader.js and .wasm, in a Web Worker the page starts:
// platform/ReadingWorkerEmscripten.cpp). Each job the page posts is read and checked by ReadingJob.hpp's
// run_reading_job, whose messages go back to the page as they are made (reader_worker.pre.js has the worker's
// side of the messages).
#include <emscripten.h>

#include <cstdint>
#include <string>

#include "app/ReadingJob.hpp"

namespace {

std::string g_bytes;  // the tape of the next job (essi_reader_buffer)

// clang-format off
EM_JS(void, essi_reader_post, (std::uint32_t job, char kind, const char* body, std::size_t len), {
    const data = new Uint8Array(len + 1);
    data[0] = kind;
    data.set(HEAPU8.subarray(body, body + len), 1);
    postMessage({job: job, data: data.buffer}, [data.buffer]);
});
// clang-format on

}  // namespace

extern "C" {

// Room for the next job's tape of `size` bytes, which the worker's script writes there.
EMSCRIPTEN_KEEPALIVE char* essi_reader_buffer(std::size_t size) {
    g_bytes.assign(size, '\0');
    return g_bytes.data();
}

// Reads and checks the tape put in essi_reader_buffer as the request `header` says.
EMSCRIPTEN_KEEPALIVE void essi_reader_run(std::uint32_t job, const char* header, std::size_t header_len) {
    essi::viewer::run_reading_job(std::string_view(header, header_len), std::move(g_bytes),
                                  [job](essi::viewer::ReadingMessage kind, std::string_view body) {
                                      essi_reader_post(job, static_cast<char>(kind), body.data(), body.size());
                                  });
    g_bytes = std::string();
}

}  // extern "C"

int main() { return 0; }
