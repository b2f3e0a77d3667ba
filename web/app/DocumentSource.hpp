// Where LoadController's new document comes from: read on the page a slice at a time (DocumentLoader), or read by
// the reading worker (WorkerLoader). Either gives the document first, then, when its cut plan was analysed after
// it, the plan's findings among its diagnostics.
#pragma once

#include <memory>
#include <string_view>

#include "app/Document.hpp"
#include "essi/i18n.hpp"

namespace essi::viewer {

class DocumentSource {
public:
    virtual ~DocumentSource() = default;
    // Works (or waits) for about budget_ms; true when the document is ready for take().
    virtual bool step(double budget_ms) = 0;
    [[nodiscard]] virtual std::unique_ptr<Document> take() = 0;
    // After take(): the cut plan's findings are still to come (step_plan).
    [[nodiscard]] virtual bool plan_pending() const = 0;
    // Works for about budget_ms on the plan; when its findings are in `doc`'s diagnostics (sorted, their marks
    // placed), true. `doc` is the document this source gave.
    virtual bool step_plan(Document& doc, double budget_ms) = 0;
    [[nodiscard]] virtual float progress() const = 0;       // 0..1
    [[nodiscard]] virtual Msg stage() const = 0;            // "indexing lines", "reading and checking", ... (ui.def)
    [[nodiscard]] virtual float plan_progress() const = 0;  // 0..1
    // The work is done on the page (its slices run between frames too), not elsewhere while the page waits.
    [[nodiscard]] virtual bool works_on_page() const { return true; }
    // Why a source that reads elsewhere read on the page after all (empty: it did not, or it reads on the page).
    [[nodiscard]] virtual std::string_view failure() const { return {}; }
};

}  // namespace essi::viewer
