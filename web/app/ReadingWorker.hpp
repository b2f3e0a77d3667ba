// The reading worker as the app sees it: a Web Worker that runs ReadingJob.hpp's job in the browser
// (platform/ReadingWorkerEmscripten.cpp), none on the desktop (PlatformServices::reading_worker() is null there).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace essi::viewer {

class ReadingWorker {
public:
    virtual ~ReadingWorker() = default;
    // The worker may start ahead of its first job (the platform's choice): its program fetched and compiled, then
    // warmed up on the built-in tapes while it waits (the page calls it once its own warm-up is done). A worker
    // already running is left so.
    virtual void prepare() = 0;
    // Hands job `job` to the worker: the request's header and the tape's bytes (both copied). A job that has not
    // finished is dropped.
    virtual void post(std::uint32_t job, std::string_view header, std::string_view bytes) = 0;
    // The page is ready for job `job`'s cut plan (it has drawn its document): the worker analyses it now.
    virtual void analyse_plan(std::uint32_t job) = 0;
    // The next message of job `job` that came (ReadingMessage's kind byte, then its body), if any.
    [[nodiscard]] virtual std::optional<std::string> receive(std::uint32_t job) = 0;
    // Job `job` is no longer wanted: its work stops, its messages are dropped.
    virtual void cancel(std::uint32_t job) = 0;
};

}  // namespace essi::viewer
