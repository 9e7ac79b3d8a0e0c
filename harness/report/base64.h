// Base64 (RFC 4648, standard alphabet, '=' padding): how report.html embeds the run's PNG
// pictures as data: URIs, so the file needs nothing beside it.
#pragma once

#include <string>
#include <string_view>

namespace tb::report {

// 3 bytes become 4 characters; the result is 4 * ceil(n / 3) characters long.
std::string base64Encode(std::string_view bytes);

}  // namespace tb::report
