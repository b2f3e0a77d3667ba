// The files `essi serve` hands out: an allow-list, never a folder. The viewer's page and its files from the web
// root (index.html, essi_viewer.js/.wasm/.data, share_store.js, favicon.ico, essi_cjk.ttc) or from the viewer
// compiled into essi (embedded_web.hpp: every file but the page gzip-encoded where the client takes it), and the
// example tapes (*.esi, *.eia) with their list; everything else is a JSON 404. Files are streamed (64 KB at a
// time), not read whole.
#pragma once

#if defined(ESSI_HAVE_HTTPLIB)
#include <string>

namespace httplib {
class Server;
}

namespace essi::native {

struct StaticFiles {
    std::string web_root;        // "" = the viewer compiled into essi
    std::string examples_dir;    // "" = no examples
    std::string share_store_js;  // used when the web root has no share_store.js
};

void add_static_routes(httplib::Server& server, const StaticFiles& files);

}  // namespace essi::native
#endif
