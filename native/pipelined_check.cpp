#include "pipelined_check.hpp"

#include "plate_runner.hpp"
#include "thread_pool.hpp"

namespace essi::native {

CheckResult check_tape_pipelined(std::string_view bytes, const TapeSetup& setup, std::size_t max_diagnostics,
                                 bool parts) {
    CheckResult r = check_tape_pipelined(bytes, setup.profile, setup.format, max_diagnostics, parts);
    record_setup(r, setup);
    return r;
}

CheckResult check_tape_pipelined(std::string_view bytes, const Profile& profile, InputFormat format,
                                 std::size_t max_diagnostics, bool parts) {
    // (without threads, e.g. under Emscripten without pthreads: the same check on this thread)
    if (bytes.size() < kPipelineMinBytes || !kHaveThreads)
        return check_tape(bytes, profile, format, max_diagnostics, parts);
    // The cut plan's plates, analysed by whichever thread would otherwise wait for the other.
    SharedPlateRunner plates;
    TapeChecker checker(bytes, profile);
    checker.set_max_diagnostics(max_diagnostics);
    checker.set_plate_runner(&plates);
    if (parts) checker.find_parts();
    PipelinedCheck::Hooks hooks;
    hooks.idle = [&plates] { return plates.run_one(); };
    PipelinedCheck(checker, TapeReader(bytes, profile, format), std::move(hooks)).run();
    CheckResult r = checker.finish();
    r.input = format;
    r.profile = profile.name;
    return r;
}

}  // namespace essi::native
