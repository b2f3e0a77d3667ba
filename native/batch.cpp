#include "batch.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include "essi/sniff.hpp"
#include "essi/text.hpp"
#include "essi/pipeline.hpp"
#include "file_io.hpp"
#include "essi/parts.hpp"
#include "pipelined_check.hpp"
#include "thread_pool.hpp"

namespace essi::native {

namespace fs = std::filesystem;

std::vector<std::string> default_tape_extensions() { return {".esi", ".essi", ".ess", ".nc", ".txt"}; }

std::vector<std::string> parse_extension_list(std::string_view list) {
    std::vector<std::string> out;
    std::string cur;
    auto flush = [&] {
        if (cur.empty() || cur == ".") {
            cur.clear();
            return;
        }
        if (cur[0] != '.') cur.insert(cur.begin(), '.');
        if (std::find(out.begin(), out.end(), cur) == out.end()) out.push_back(cur);
        cur.clear();
    };
    for (char c : list) {
        if (c == ',' || c == ' ' || c == '\t' || c == ';') {
            flush();
        } else {
            cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    flush();
    return out;
}

bool sniff_tape_file(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) return false;
    char buf[kSniffBytes];
    const std::size_t n = std::fread(buf, 1, sizeof buf, f.get());
    return looks_like_essi(std::string_view(buf, n));
}

namespace {

// Whether a file found in a directory is checked: a tape extension, or (unless --no-sniff) a first KB that looks
// like a tape (essi/sniff.hpp), whatever its extension (or none).
bool takes_file(const fs::path& file, const ExpandOptions& options) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool known = std::find(options.extensions.begin(), options.extensions.end(), ext) != options.extensions.end();
    return known || (options.sniff && sniff_tape_file(file.string()));
}

// The files of `dir` and its subfolders that are taken, in `found`; a folder that cannot be listed (no permission,
// gone while listed) is an error naming it, and the walk goes on with the rest. Symbolic links to folders are not
// followed (no loops).
void walk_directory(const std::string& dir, const ExpandOptions& options, std::vector<std::string>& found,
                    std::vector<std::string>& errors) {
    std::vector<fs::path> pending{fs::path(dir)};
    while (!pending.empty()) {
        const fs::path folder = std::move(pending.back());
        pending.pop_back();
        std::error_code ec;
        fs::directory_iterator it(folder, ec), end;
        for (; !ec && it != end; it.increment(ec)) {
            std::error_code entry_ec;
            if (it->is_symlink(entry_ec)) {
                if (it->is_regular_file(entry_ec) && takes_file(it->path(), options))
                    found.push_back(it->path().string());
            } else if (it->is_directory(entry_ec)) {
                pending.push_back(it->path());
            } else if (it->is_regular_file(entry_ec) && takes_file(it->path(), options)) {
                found.push_back(it->path().string());
            }
        }
        if (ec) errors.push_back("cannot read " + display_text(folder.string()) + ": " + ec.message());
    }
}

}  // namespace

std::vector<std::string> expand_paths(const std::vector<std::string>& args, const ExpandOptions& options,
                                      std::vector<std::string>& errors) {
    std::vector<std::string> files;
    for (const std::string& path : args) {
        std::error_code ec;
        if (path == "-" || !fs::is_directory(path, ec)) {
            files.push_back(path);
            continue;
        }
        std::vector<std::string> found;
        walk_directory(path, options, found, errors);
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

void check_batch(const std::vector<std::string>& files, const TapeRequest& request, const BatchOptions& options,
                 const std::function<void(BatchItem&&)>& emit) {
    std::vector<BatchItem> items(files.size());
    // A pipelined check needs a second thread: use it when there is a core to spare for it.
    const bool pipelined = options.jobs >= 2;
    auto work = [&](std::size_t i) {
        const auto t0 = std::chrono::steady_clock::now();
        BatchItem& item = items[i];
        item.report.path = files[i];
        ReadResult file = read_tape_file(files[i], options.max_size, options.lang);
        if (!file.ok) {
            item.error = file.error;
        } else {
            item.read_ok = true;
            const TapeSetup setup = request.setup(file.bytes);
            item.report.result = pipelined
                                     ? check_tape_pipelined(file.bytes, setup, options.max_diagnostics, options.parts)
                                     : check_tape(file.bytes, setup, options.max_diagnostics, options.parts);
            limit_diagnostics(item.report.result, options.max_diagnostics);  // (with the setup's note)
        }
        item.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    for_each_ordered(files.size(), options.jobs, work, [&](std::size_t i) {
        emit(std::move(items[i]));
        items[i] = BatchItem{};  // free it now
    });
}

}  // namespace essi::native
