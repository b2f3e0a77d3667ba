// Replays a saved fuzz corpus without libFuzzer: every regular file of every folder given on the command
// line (or a single file) goes through LLVMFuzzerTestOneInput, in name order. Built natively (with ASan +
// UBSan when ESSI_REPLAY_SANITIZE is on) and with em++ (corpus preloaded at /fuzz_corpus), once per target,
// and registered with ctest as `fuzz_replay_NAME`.
//
// Exit code: 0 when every input ran; a crash, sanitizer report, uncaught exception or broken invariant
// aborts the process (non-zero); 1 when no input was found (an empty corpus must not pass silently).
#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool is_dir(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// Regular files directly inside `dir`, sorted (POSIX dirent: works natively and in the Emscripten FS).
std::vector<std::string> files_in(const std::string& dir) {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            if (name == "." || name == "..") continue;
            const std::string path = dir + "/" + name;
            if (!is_dir(path)) out.push_back(path);
        }
        ::closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR_OR_FILE...\n", argv[0]);
        return 2;
    }
    std::size_t count = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::vector<std::string> inputs = is_dir(arg) ? files_in(arg) : std::vector<std::string>{arg};
        for (const std::string& path : inputs) {
            std::ifstream in(path, std::ios::binary);
            if (!in) {
                std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
                return 1;
            }
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            std::fprintf(stderr, "replay: %s (%zu bytes)\n", path.c_str(), bytes.size());
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
            ++count;
        }
    }
    if (count == 0) {
        std::fprintf(stderr, "replay: no inputs found\n");
        return 1;
    }
    std::printf("replay: %zu inputs ran without a failure\n", count);
    return 0;
}
