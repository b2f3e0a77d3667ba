#include "tape_request.hpp"

namespace essi::native {

bool parse_input_format(std::string_view text, std::optional<InputFormat>& out) {
    if (text == "auto" || text.empty()) out.reset();
    else if (text == "essi") out = InputFormat::Essi;
    else if (text == "eia") out = InputFormat::Eia;
    else return false;
    return true;
}

}  // namespace essi::native
