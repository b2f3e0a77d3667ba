#include "app/ScreenLayout.hpp"

#include <algorithm>

namespace essi::viewer {

namespace {
constexpr float kMinDrawingPx = 50;  // the drawing keeps at least this height
}

const char* sheet_tab_name(SheetTab t) {
    switch (t) {
        case SheetTab::Problems: return "problems";
        case SheetTab::Statistics: return "statistics";
        case SheetTab::Source: return "source";
        case SheetTab::Inspector: return "inspector";
    }
    return "";
}

float sheet_height(const BottomSheet& sheet, float h) {
    return sheet.open ? std::max(kSheetTabsHeight, h * kSheetOpenShare) : kSheetTabsHeight;
}

Rect compact_drawing_area(float w, float h, float top, const BottomSheet& sheet) {
    return Rect{0, top, std::max(w, kMinDrawingPx), std::max(h - top - sheet_height(sheet, h), kMinDrawingPx)};
}

}  // namespace essi::viewer
