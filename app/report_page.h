#pragma once

#include <string>

namespace sedem::app {

// A whole HTML page that opens from its folder with no server and fetches nothing: the
// style inline, no font or script from elsewhere, only the small inline script that plays a
// series of frames (an element of class "player", see frames_html in app/report_images.h).
// `title` is plain text (escaped here); `body` is HTML.
std::string html_page(const std::string& title, const std::string& body);

}  // namespace sedem::app
