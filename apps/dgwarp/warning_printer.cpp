#include "warning_printer.hpp"

#include <iostream>

namespace dgwarp::cli {

void WarningPrinter::print(const std::string& text, const std::string& where) {
    if (enabled_ && printed_.insert(text).second) std::cerr << "warning: " << where << text << "\n";
}

}  // namespace dgwarp::cli
