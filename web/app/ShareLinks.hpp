// Share links (docs/viewer.md, "Share links"): the platform makes one for the tape, the view, the selection and how
// the tape is read (the page compresses the tape into the URL, or stores it); the link or why there is none is shown
// in the Share link window.
#pragma once

#include <string>

#include "app/Language.hpp"
#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/PlatformServices.hpp"
#include "app/Session.hpp"
#include "app/UiState.hpp"

namespace essi::viewer {

class ShareLinks {
public:
    ShareLinks(const Session& session, const Navigation& navigation, Notices& notices, UiState& ui,
               PlatformServices& platform)
        : session_(session), navigation_(navigation), notices_(notices), ui_(ui), platform_(platform) {}

    void share();                // the Share button and S
    void done(std::string url);  // the link is made (and copied)
    void failed(Phrase why);     // it could not be made
    // The share link, or why there is none (the Share link window, state().share_url).
    [[nodiscard]] std::string text() const;
    // "c=X,Y,ZOOM&l=LINE&p=PROFILE[&pj=JSON]&i=FORMAT": the view, the selection and how the tape is read.
    [[nodiscard]] std::string query() const;

private:
    const Session& session_;
    const Navigation& navigation_;
    Notices& notices_;
    UiState& ui_;
    PlatformServices& platform_;
    std::string url_;  // the last link
    Phrase problem_;   // or why the last one could not be made
};

}  // namespace essi::viewer
