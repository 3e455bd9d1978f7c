#include "support/text/setting_names.hpp"

namespace sphkern {

std::string setting_named(std::string_view key) { return "{{" + std::string(key) + "}}"; }

std::string spell_settings(std::string_view message, const std::function<std::string(std::string_view)>& spell)
{
    std::string spelled;
    std::size_t at = 0;
    while (true) {
        const std::size_t open = message.find("{{", at);
        const std::size_t close = open == std::string_view::npos ? open : message.find("}}", open + 2);
        if (close == std::string_view::npos) break;
        const std::string_view key = message.substr(open + 2, close - open - 2);
        // Only a key (lower case, digits, _) is a mark: other braces are the message's own.
        const bool mark =
            !key.empty() && key.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string_view::npos;
        spelled.append(message.substr(at, open - at));
        spelled += mark ? spell(key) : std::string(message.substr(open, close + 2 - open));
        at = close + 2;
    }
    spelled.append(message.substr(at));
    return spelled;
}

} // namespace sphkern
