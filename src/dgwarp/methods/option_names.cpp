#include "dgwarp/methods/option_names.hpp"

#include <algorithm>

namespace dgwarp {

std::optional<Method> option_method(std::string_view name) {
    if (name.starts_with("--")) name.remove_prefix(2);
    for (const MethodOptionName& option : method_option_names)
        if (option.name.size() == name.size() &&
            std::equal(name.begin(), name.end(), option.name.begin(),
                       [](char a, char b) { return a == b || (a == '_' && b == '-'); }))
            return option.method;
    return std::nullopt;
}

}  // namespace dgwarp
