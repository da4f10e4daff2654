// `frameray --version`: frameray's version and those of the libraries it
// renders with, one per line.
#pragma once

#include <string>

namespace frameray::app {

std::string versionText();

}  // namespace frameray::app
