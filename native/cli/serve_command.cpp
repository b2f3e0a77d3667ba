// essi serve: the browser viewer, the example tapes and the check/share API over HTTP (serve.hpp; docs/serve.md).
// Not in the npm package's build (no sockets there).
#include <map>
#include <string>

#include "cli/cli_options.hpp"
#include "cli/commands.hpp"
#include "serve.hpp"

namespace essi::cli {
namespace {

void add_limit_options(CLI::App* serve, native::ServeOptions& o) {
    const auto limit_option = [serve](const char* name, auto& value, int max, const char* help) {
        serve->add_option(name, value, help)->check(CLI::Range(1, max))->capture_default_str();
    };
    limit_option("--threads", o.threads, 1024, "Requests handled at once (each connection waits in its own thread)");
    limit_option("--max-connections", o.max_connections, 100000, "Connections open at once (more wait to be accepted)");
    limit_option("--max-client-connections", o.max_client_connections, 100000,
                 "Connections open at once from one client address (more get 429)");
    limit_option("--request-timeout", o.request_timeout_s, 3600,
                 "Seconds a client has to send its request line and headers (and the grace before "
                 "--min-transfer-rate)");
    limit_option("--body-timeout", o.body_timeout_s, 86400,
                 "Seconds a request body may take in all; also the longest wait for a slot (then 503)");
    limit_option("--max-large-requests", o.max_large_requests, 1024,
                 "Requests with a body over 1 MB handled at once (bounds the server's memory)");
    limit_option("--max-checks", o.max_checks, 1024,
                 "Checks and conversions running at once, whatever the size of their tape (bounds the server's "
                 "memory)");
    limit_option("--max-diagnostics", o.max_diagnostics, 100000000,
                 "Diagnostics in an /api/check or /api/convert answer (the rest are counted: diagnostics_omitted)");
}

void add_size_options(CLI::App* serve, native::ServeOptions& o) {
    const auto size_option = [serve](const char* name, std::uint64_t& value, const char* help) {
        add_size_option(serve, name, value, help)->capture_default_str();
    };
    size_option("--max-body", o.max_body, "Largest request body in bytes (suffixes KB MB GB: 1024-based)");
    size_option("--max-store", o.max_store, "Largest total size of the stored shares (oldest go first)");
    size_option("--min-transfer-rate", o.min_transfer_rate,
                "Slowest average rate, per second, of a request body or a response after the first "
                "--request-timeout seconds (default 1MB)");
}

}  // namespace

Subcommand define_serve(CLI::App& essi) {
    auto o = std::make_shared<native::ServeOptions>();
    o->web_root = ESSI_DEFAULT_WEB_ROOT;
    o->examples_dir = ESSI_DEFAULT_EXAMPLES_DIR;
    o->share_store_js = ESSI_DEFAULT_SHARE_STORE_JS;
    CLI::App* serve =
        essi.add_subcommand("serve", "Serve the browser viewer, the example tapes and the check/share API");
    serve->add_option("--host", o->host, "Address to listen on")->capture_default_str();
    serve->add_option("--port", o->port, "Port (0 picks a free one)")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    serve
        ->add_option("--web-root", o->web_root,
                     "The built viewer (index.html, essi_viewer.js/.wasm); empty: the viewer compiled into essi "
                     "(make dist)")
        ->capture_default_str();
    serve->add_option("--examples", o->examples_dir, "Folder of example tapes served at /examples/")
        ->capture_default_str();
    serve
        ->add_option("--data", o->data_dir,
                     "Folder of the share store (SQLite); default $XDG_DATA_HOME/essikit, else ./essi-data")
        ->type_name("DIR");
    add_size_options(serve, *o);
    add_limit_options(serve, *o);
    serve
        ->add_option("--allowed-host", o->allowed_hosts,
                     "A Host name served besides localhost, 127.0.0.1, ::1 and --host (repeatable; DNS rebinding)")
        ->type_name("NAME");
    const std::map<std::string, std::int64_t> seconds_per{{"s", 1}, {"m", 60}, {"h", 3600}, {"d", 86400}};
    serve->add_option("--share-ttl", o->share_ttl_s, "How long a share lives (suffixes s m h d; default 30d)")
        ->transform(CLI::AsNumberWithUnit(seconds_per, CLI::AsNumberWithUnit::CASE_SENSITIVE))
        ->check(CLI::PositiveNumber)
        ->type_name("DURATION");
    serve->add_option("--share-rate", o->share_rate, "Uploads per minute per client address (0: no limit)")
        ->capture_default_str();
    return {serve, [o] { return native::run_serve(*o); }};
}

}  // namespace essi::cli
