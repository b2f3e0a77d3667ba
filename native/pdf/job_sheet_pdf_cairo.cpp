// The job sheet as PDF through cairo's PDF surface, its text laid out by pango: the module essi-pdf.so that essi
// loads when it writes a PDF (native/job_sheet_pdf.hpp, pdf/job_sheet_pdf_module.cpp). Every
// length here is in mm on paper (the context is scaled from cairo's points once). Fonts: DejaVu Sans, and for what
// it lacks (Chinese) WenQuanYi Micro Hei, the viewer's CJK font, both made known to fontconfig from the files the
// build names (ESSI_LATIN_FONT, ESSI_CJK_FONT); cairo embeds the glyphs used as subsets with their Unicode, so
// that the text can be searched and copied.
//
// The pages are laid out twice: once to count them (nothing drawn), then drawn with "page N of M".
#include "job_sheet_pdf.hpp"

#include <algorithm>
#include <mutex>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <cairo-pdf.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>
#include <pango/pangocairo.h>

namespace essi::native {

namespace {

constexpr double kPtPerMm = 72.0 / 25.4;
constexpr const char* kFontFamilies = "DejaVu Sans, WenQuanYi Micro Hei";

struct Font {
    double size_pt;
    bool bold = false;
};
constexpr Font kTitleFont{16, true}, kTapeFont{11}, kHeadingFont{11, true}, kBodyFont{8.5}, kHeaderCellFont{8.5, true},
    kSmallFont{7}, kLabelFont{kSheetLabelHeightMm * kPtPerMm, true};

// Layout (mm): where the content ends above the footer, the footer's line, the fields' label column, cell padding.
constexpr double kContentBottomMm = kSheetPageHeightMm - kSheetMarginMm - 6;
constexpr double kFooterTopMm = kSheetPageHeightMm - kSheetMarginMm - 3;
constexpr double kFieldLabelWidthMm = 50;
constexpr double kCellPadMm = 1.5, kRowPadMm = 0.6;
constexpr double kHeadingGapMm = 5, kMinTableColumnMm = 20;

struct Rgb {
    double r, g, b;
};
Rgb rgb(std::string_view hex) {  // "#rrggbb"
    const auto byte = [&](std::size_t i) { return std::stoi(std::string(hex.substr(i, 2)), nullptr, 16) / 255.0; };
    return {byte(1), byte(3), byte(5)};
}
constexpr Rgb kText{0.125, 0.125, 0.125}, kMuted{0.4, 0.4, 0.4}, kRule{0.6, 0.6, 0.6}, kFaint{0.87, 0.87, 0.87},
    kHeaderFill{0.93, 0.93, 0.93};

// The viewer's fonts made known to fontconfig (before pango's first use), once a process.
void add_fonts() {
    static std::once_flag once;
    std::call_once(once, [] {
        FcConfig* config = FcConfigGetCurrent();
        for (const char* file : {ESSI_LATIN_FONT, ESSI_CJK_FONT})
            FcConfigAppFontAddFile(config, reinterpret_cast<const FcChar8*>(file));
    });
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}
cairo_status_t discard_bytes(void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; }

// "2026-11-27 14:05 UTC" (sheet_date_text) as PDF metadata wants it: "2026-11-27T14:05:00Z".
std::string pdf_date(const std::string& date) {
    return date.size() >= 16 ? date.substr(0, 10) + "T" + date.substr(11, 5) + ":00Z" : std::string();
}

// One pass over the sheet: text measured and, when `draw`, drawn; pages counted.
class Pages {
public:
    Pages(cairo_t* cr, const JobSheet& sheet, bool draw, int total)
        : cr_(cr), sheet_(sheet), draw_(draw), total_(total), context_(pango_cairo_create_context(cr)) {
        cairo_font_options_t* options = cairo_font_options_create();
        cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
        pango_cairo_context_set_font_options(context_, options);
        cairo_font_options_destroy(options);
        pango_context_set_round_glyph_positions(context_, FALSE);
        pango_context_set_language(context_, pango_language_from_string(lang_code(sheet.lang).data()));
    }
    ~Pages() { g_object_unref(context_); }
    Pages(const Pages&) = delete;
    Pages& operator=(const Pages&) = delete;

    void write();
    [[nodiscard]] int pages() const { return page_; }

private:
    // A laid-out text (pango), owned.
    class Text {
    public:
        Text(PangoContext* context, const std::string& text, Font font, double width_mm, PangoAlignment align)
            : layout_(pango_layout_new(context)) {
            PangoFontDescription* desc = pango_font_description_from_string(kFontFamilies);
            pango_font_description_set_absolute_size(desc, font.size_pt / kPtPerMm * PANGO_SCALE);
            pango_font_description_set_weight(desc, font.bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
            pango_layout_set_font_description(layout_, desc);
            pango_font_description_free(desc);
            if (width_mm > 0) {
                pango_layout_set_width(layout_, static_cast<int>(width_mm * PANGO_SCALE));
                pango_layout_set_wrap(layout_, PANGO_WRAP_WORD_CHAR);
                pango_layout_set_alignment(layout_, align);
            }
            pango_layout_set_text(layout_, text.data(), static_cast<int>(text.size()));
        }
        ~Text() {
            if (layout_) g_object_unref(layout_);
        }
        Text(Text&& o) noexcept : layout_(std::exchange(o.layout_, nullptr)) {}
        Text(const Text&) = delete;
        Text& operator=(const Text&) = delete;
        Text& operator=(Text&&) = delete;
        [[nodiscard]] double width() const { return size().first; }
        [[nodiscard]] double height() const { return size().second; }
        [[nodiscard]] PangoLayout* layout() const { return layout_; }

    private:
        [[nodiscard]] std::pair<double, double> size() const {
            int w = 0, h = 0;
            pango_layout_get_size(layout_, &w, &h);
            return {static_cast<double>(w) / PANGO_SCALE, static_cast<double>(h) / PANGO_SCALE};
        }
        PangoLayout* layout_;
    };

    [[nodiscard]] Text text(const std::string& s, Font f, double width_mm = 0,
                            PangoAlignment a = PANGO_ALIGN_LEFT) const {
        return Text(context_, s, f, width_mm, a);
    }
    void show(const Text& t, double x, double y, Rgb color) {
        if (!draw_) return;
        cairo_set_source_rgb(cr_, color.r, color.g, color.b);
        cairo_move_to(cr_, x, y);
        pango_cairo_show_layout(cr_, t.layout());
    }
    void fill_rect(double x, double y, double w, double h, Rgb color) {
        if (!draw_) return;
        cairo_set_source_rgb(cr_, color.r, color.g, color.b);
        cairo_rectangle(cr_, x, y, w, h);
        cairo_fill(cr_);
    }
    void rule(double y, double width_mm, Rgb color) {
        if (!draw_) return;
        cairo_set_source_rgb(cr_, color.r, color.g, color.b);
        cairo_set_line_width(cr_, width_mm);
        cairo_move_to(cr_, kSheetMarginMm, y);
        cairo_line_to(cr_, kSheetMarginMm + kSheetContentWidthMm, y);
        cairo_stroke(cr_);
    }

    // Room for `h` mm more on this page, else the next page.
    void need(double h) {
        if (y_ + h > kContentBottomMm && y_ > kSheetMarginMm) next_page();
    }
    void next_page() {
        footer();
        if (draw_) cairo_show_page(cr_);
        ++page_;
        y_ = kSheetMarginMm;
    }
    void footer();

    void title();
    void heading(const SheetSection& s, double first_row_h);
    [[nodiscard]] std::pair<Text, Text> field(const SheetField& f) const;
    [[nodiscard]] double fields_height(const SheetSection& s) const;
    void fields(const SheetSection& s);
    void table(const SheetTable& t);
    [[nodiscard]] std::vector<double> column_widths(const SheetTable& t) const;
    // A table's row laid out in its columns, and its height.
    struct Row {
        std::vector<Text> cells;
        double height = 0;
    };
    [[nodiscard]] Row lay_out_row(const SheetTable& t, const std::vector<std::string>& texts, Font f,
                                  const std::vector<double>& widths) const;
    void show_row(const Row& row, const std::vector<double>& widths, std::optional<Severity> severity);
    void drawing();
    void draw_motions(double x0, double y0);
    void draw_marks(double x0, double y0);
    [[nodiscard]] double legend_height() const;
    void legend();
    void legend_sample(const SheetLegendEntry& e, double x, double y);
    void set_stroke(const SheetStroke& s);
    void pierce(Point c);
    void mark(Point c, Severity s);
    void label(Point c, const std::string& s);
    void note(const std::string& s);

    cairo_t* cr_;
    const JobSheet& sheet_;
    bool draw_;
    int total_;
    PangoContext* context_;
    int page_ = 1;
    double y_ = kSheetMarginMm;
};

void Pages::write() {
    title();
    for (const SheetSection& s : sheet_.sections) {
        if (s.drawing) {
            heading(s, sheet_.drawing.height_mm + legend_height());
            drawing();
        } else {
            // A section of fields stays on one page; a table may run on once its header and first row are on it.
            const double first = s.fields.empty() ? text(s.note, kBodyFont).height() * 2 : fields_height(s);
            heading(s, std::min(first, kContentBottomMm - kSheetMarginMm - 20));
            if (!s.fields.empty()) fields(s);
            if (s.table) table(*s.table);
        }
        if (!s.note.empty()) note(s.note);
    }
    footer();
    if (draw_) cairo_show_page(cr_);
}

void Pages::footer() {
    const Text left = text(sheet_.footer, kSmallFont, kSheetContentWidthMm * 0.75);
    const Text right = text(format_template(sheet_.page_template, sheet_.lang, {page_, total_}), kSmallFont,
                            kSheetContentWidthMm * 0.25, PANGO_ALIGN_RIGHT);
    rule(kFooterTopMm, 0.2, kFaint);
    show(left, kSheetMarginMm, kFooterTopMm + 0.8, kMuted);
    show(right, kSheetMarginMm + kSheetContentWidthMm * 0.75, kFooterTopMm + 0.8, kMuted);
}

void Pages::title() {
    const Text t = text(sheet_.title, kTitleFont, kSheetContentWidthMm);
    show(t, kSheetMarginMm, y_, kText);
    y_ += t.height() + 0.5;
    const Text tape = text(sheet_.tape, kTapeFont, kSheetContentWidthMm);
    show(tape, kSheetMarginMm, y_, kText);
    y_ += tape.height();
}

void Pages::heading(const SheetSection& s, double first_row_h) {
    const Text t = text(s.title, kHeadingFont, kSheetContentWidthMm);
    need(kHeadingGapMm + t.height() + 2 + first_row_h);
    y_ += kHeadingGapMm;
    show(t, kSheetMarginMm, y_, kText);
    y_ += t.height() + 0.5;
    rule(y_, 0.3, kRule);
    y_ += 1.5;
}

// A field: the label in its column, the value beside it (both wrap).
std::pair<Pages::Text, Pages::Text> Pages::field(const SheetField& f) const {
    return {text(f.label, kBodyFont, kFieldLabelWidthMm - 2),
            text(f.value, kBodyFont, kSheetContentWidthMm - kFieldLabelWidthMm)};
}

double Pages::fields_height(const SheetSection& s) const {
    double h = 0;
    for (const SheetField& f : s.fields) {
        const auto [label, value] = field(f);
        h += std::max(label.height(), value.height()) + kRowPadMm;
    }
    return h;
}

void Pages::fields(const SheetSection& s) {
    for (const SheetField& f : s.fields) {
        const auto [label, value] = field(f);
        const double h = std::max(label.height(), value.height()) + kRowPadMm;
        need(h);
        show(label, kSheetMarginMm, y_, kMuted);
        show(value, kSheetMarginMm + kFieldLabelWidthMm, y_, kText);
        y_ += h;
    }
}

// Each column as wide as its widest cell; when they do not fit, the widest takes what the others leave (its cells
// wrap), and if that is too little every column shrinks in proportion.
std::vector<double> Pages::column_widths(const SheetTable& t) const {
    std::vector<double> widths(t.columns.size(), 0);
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
        widths[c] = text(t.columns[c], kHeaderCellFont).width();
        for (const auto& row : t.rows) widths[c] = std::max(widths[c], text(row[c], kBodyFont).width());
        widths[c] += 2 * kCellPadMm;
    }
    double sum = 0;
    for (const double w : widths) sum += w;
    if (sum <= kSheetContentWidthMm) {
        widths.back() += kSheetContentWidthMm - sum;
        return widths;
    }
    const auto widest = std::max_element(widths.begin(), widths.end());
    const double others = sum - *widest;
    if (kSheetContentWidthMm - others >= kMinTableColumnMm) {
        *widest = kSheetContentWidthMm - others;
        return widths;
    }
    for (double& w : widths) w *= kSheetContentWidthMm / sum;
    return widths;
}

Pages::Row Pages::lay_out_row(const SheetTable& t, const std::vector<std::string>& texts, Font f,
                              const std::vector<double>& widths) const {
    Row row;
    for (std::size_t c = 0; c < texts.size(); ++c) {
        row.cells.push_back(
            text(texts[c], f, widths[c] - 2 * kCellPadMm, t.numeric[c] ? PANGO_ALIGN_RIGHT : PANGO_ALIGN_LEFT));
        row.height = std::max(row.height, row.cells.back().height());
    }
    row.height += 2 * kRowPadMm;
    return row;
}

// A row at y_ (a diagnostic's first cell in its severity's colour).
void Pages::show_row(const Row& row, const std::vector<double>& widths, std::optional<Severity> severity) {
    double x = kSheetMarginMm;
    for (std::size_t c = 0; c < row.cells.size(); ++c) {
        show(row.cells[c], x + kCellPadMm, y_ + kRowPadMm,
             severity && c == 0 ? rgb(sheet_mark_color(*severity)) : kText);
        x += widths[c];
    }
}

// The header row on a grey band, again at the top of every page the table runs onto.
void Pages::table(const SheetTable& t) {
    const std::vector<double> widths = column_widths(t);
    const Row header = lay_out_row(t, t.columns, kHeaderCellFont, widths);
    const auto put_header = [&] {
        fill_rect(kSheetMarginMm, y_, kSheetContentWidthMm, header.height, kHeaderFill);
        show_row(header, widths, std::nullopt);
        y_ += header.height;
    };
    put_header();
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const Row row = lay_out_row(t, t.rows[r], kBodyFont, widths);
        if (y_ + row.height > kContentBottomMm) {
            next_page();
            put_header();
        }
        show_row(row, widths, t.row_severity[r]);
        y_ += row.height;
        rule(y_, 0.2, kFaint);
    }
}

void Pages::drawing() {
    const SheetDrawing& d = sheet_.drawing;
    const double x0 = kSheetMarginMm + (kSheetContentWidthMm - d.width_mm) / 2, y0 = y_;
    if (draw_) {
        cairo_save(cr_);
        cairo_rectangle(cr_, x0, y0, d.width_mm, d.height_mm);
        cairo_clip(cr_);
        draw_motions(x0, y0);
        draw_marks(x0, y0);
        cairo_restore(cr_);
        cairo_set_source_rgb(cr_, 0.73, 0.73, 0.73);
        cairo_set_line_width(cr_, 0.2);
        cairo_rectangle(cr_, x0, y0, d.width_mm, d.height_mm);
        cairo_stroke(cr_);
    }
    y_ += d.height_mm + 1.5;
    legend();
}

void Pages::draw_motions(double x0, double y0) {
    const SheetDrawing& d = sheet_.drawing;
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    for (const MotionKind kind : kSheetDrawOrder) {
        set_stroke(sheet_stroke(kind));
        for (const std::vector<Point>& line : d.paths[static_cast<std::size_t>(kind)]) {
            if (line.size() < 2) continue;
            for (std::size_t i = 0; i < line.size(); ++i) {
                const Point p = d.to_paper(line[i]);
                (i == 0 ? cairo_move_to : cairo_line_to)(cr_, x0 + p.x, y0 + p.y);
            }
            cairo_stroke(cr_);
        }
    }
    cairo_set_dash(cr_, nullptr, 0, 0);
    for (const Point& p : d.pierces) {
        const Point c = d.to_paper(p);
        pierce({x0 + c.x, y0 + c.y});
    }
}

void Pages::set_stroke(const SheetStroke& s) {
    const Rgb c = rgb(s.color);
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_set_line_width(cr_, s.width_mm);
    const double dashes[] = {s.dash_mm, s.dash_mm};
    cairo_set_dash(cr_, dashes, s.dash_mm > 0 ? 2 : 0, 0);
}

void Pages::pierce(Point c) {
    const Rgb color = rgb(kSvgPierceColor);
    cairo_set_source_rgb(cr_, color.r, color.g, color.b);
    cairo_set_line_width(cr_, 0.2);
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, c.x, c.y, kSheetPierceRadiusMm, 0, 2 * G_PI);
    cairo_stroke(cr_);
}

void Pages::draw_marks(double x0, double y0) {
    const SheetDrawing& d = sheet_.drawing;
    for (const SheetDrawing::Mark& m : d.marks) {
        const Point c = d.to_paper(m.at);
        mark({x0 + c.x, y0 + c.y}, m.severity);
    }
    for (const SheetDrawing::Label& l : d.labels) {
        const Point c = d.to_paper(l.at);
        label({x0 + c.x, y0 + c.y}, l.text);
    }
}

void Pages::mark(Point c, Severity s) {
    const Rgb color = rgb(sheet_mark_color(s));
    const double r = kSheetMarkRadiusMm;
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, c.x, c.y, r, 0, 2 * G_PI);
    cairo_set_source_rgba(cr_, color.r, color.g, color.b, 0.3);
    cairo_fill_preserve(cr_);
    cairo_set_source_rgb(cr_, color.r, color.g, color.b);
    cairo_set_line_width(cr_, 0.3);
    cairo_stroke(cr_);
    if (s != Severity::Error) return;
    cairo_move_to(cr_, c.x - r, c.y - r);
    cairo_line_to(cr_, c.x + r, c.y + r);
    cairo_move_to(cr_, c.x - r, c.y + r);
    cairo_line_to(cr_, c.x + r, c.y - r);
    cairo_stroke(cr_);
}

// A part's number centred on `c`, dark with a white outline (readable over the lines).
void Pages::label(Point c, const std::string& s) {
    const Text t = text(s, kLabelFont);
    cairo_move_to(cr_, c.x - t.width() / 2, c.y - t.height() / 2);
    pango_cairo_layout_path(cr_, t.layout());
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_set_line_width(cr_, 0.6);
    cairo_stroke_preserve(cr_);
    cairo_set_source_rgb(cr_, kText.r, kText.g, kText.b);
    cairo_fill(cr_);
}

// The legend's entries in rows: a sample 8 x 3 mm and the name, 5 mm between entries.
constexpr double kSampleWidthMm = 8, kSampleHeightMm = 3, kLegendGapMm = 5;

double Pages::legend_height() const {
    double x = 0, rows = sheet_.legend.empty() ? 0 : 1;
    for (const SheetLegendEntry& e : sheet_.legend) {
        const double w = kSampleWidthMm + 1 + text(e.text, kBodyFont).width();
        if (x > 0 && x + w > kSheetContentWidthMm) {
            ++rows;
            x = 0;
        }
        x += w + kLegendGapMm;
    }
    return rows * (kSampleHeightMm + 1.5);
}

void Pages::legend() {
    double x = 0;
    const double row_h = kSampleHeightMm + 1.5;
    for (const SheetLegendEntry& e : sheet_.legend) {
        const Text t = text(e.text, kBodyFont);
        const double w = kSampleWidthMm + 1 + t.width();
        if (x > 0 && x + w > kSheetContentWidthMm) {
            x = 0;
            y_ += row_h;
        }
        legend_sample(e, kSheetMarginMm + x, y_);
        show(t, kSheetMarginMm + x + kSampleWidthMm + 1, y_ + (kSampleHeightMm - t.height()) / 2, kText);
        x += w + kLegendGapMm;
    }
    if (!sheet_.legend.empty()) y_ += row_h;
}

void Pages::legend_sample(const SheetLegendEntry& e, double x, double y) {
    if (!draw_) return;
    const Point centre{x + kSampleWidthMm / 2, y + kSampleHeightMm / 2};
    switch (e.sample) {
        case SheetLegendEntry::Sample::Stroke:
            set_stroke(sheet_stroke(e.kind));
            cairo_move_to(cr_, x + 0.5, centre.y);
            cairo_line_to(cr_, x + kSampleWidthMm - 0.5, centre.y);
            cairo_stroke(cr_);
            cairo_set_dash(cr_, nullptr, 0, 0);
            break;
        case SheetLegendEntry::Sample::Pierce: pierce(centre); break;
        case SheetLegendEntry::Sample::Mark: mark(centre, e.severity); break;
        case SheetLegendEntry::Sample::Label: label(centre, "1"); break;
    }
}

void Pages::note(const std::string& s) {
    const Text t = text(s, kBodyFont, kSheetContentWidthMm);
    need(t.height() + 1);
    y_ += 0.8;
    show(t, kSheetMarginMm, y_, kMuted);
    y_ += t.height();
}

// One pass on a PDF surface writing to `closure` with `write`; the pages it took.
int lay_out(const JobSheet& sheet, cairo_write_func_t write, void* closure, bool draw, int total, std::string& error) {
    cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(write, closure, kSheetPageWidthMm * kPtPerMm,
                                                                   kSheetPageHeightMm * kPtPerMm);
    if (draw) {
        const std::string title = sheet.title + ": " + sheet.tape, date = pdf_date(sheet.date);
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, title.c_str());
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "essi report");
        if (!date.empty()) {
            cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
            cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_MOD_DATE, date.c_str());
        }
    }
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, kPtPerMm, kPtPerMm);
    int pages = 0;
    {
        Pages p(cr, sheet, draw, total);
        p.write();
        pages = p.pages();
    }
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        error = cairo_status_to_string(status);
        return 0;
    }
    return pages;
}

}  // namespace

}  // namespace essi::native

// The module's two entry points (native/job_sheet_pdf.hpp: kPdfModuleBuild, PdfWriterFunction).
extern "C" [[gnu::visibility("default")]] const char* essi_pdf_module_build() { return essi::native::kPdfModuleBuild; }

extern "C" [[gnu::visibility("default")]] bool essi_job_sheet_pdf(const essi::JobSheet& sheet, std::string& pdf,
                                                                  std::string& error) {
    using namespace essi::native;
    add_fonts();
    const int pages = lay_out(sheet, discard_bytes, nullptr, false, 0, error);
    if (pages == 0) return false;
    pdf.clear();
    return lay_out(sheet, append_bytes, &pdf, true, pages, error) == pages;
}
