#pragma once

#include <string>
#include <string_view>

namespace sedem::app {

// Text made safe inside an HTML element or a quoted attribute: & < > " ' as entities.
std::string html_escape(std::string_view text);

// A path relative to a page, as the URL of a link or an image: every byte but letters, digits
// and - . _ ~ / = , + percent-encoded, so that any file name (a '#', a '?', a space, a '%')
// links to that file and nothing else.
std::string url_path(std::string_view relative);

}  // namespace sedem::app
