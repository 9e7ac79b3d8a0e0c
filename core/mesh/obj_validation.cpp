#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"

namespace tb::mesh {
namespace {

std::vector<std::string_view> splitTokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

bool parseDouble(std::string_view token, double* value) {
  // strtod accepts "nan" and "inf", which we must see in order to reject them.
  std::string copy(token);
  char* end = nullptr;
  *value = std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size() && !copy.empty();
}

bool parseInt(std::string_view token, long* value) {
  auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

// tinyobjloader stores corner counts in an unsigned char.
constexpr size_t kMaxFaceCorners = 255;

// tinyobjloader stores coordinates and tag values as float: a larger finite double would
// become infinite there.
bool fitsFloat(double value) { return std::abs(value) <= std::numeric_limits<float>::max(); }

// Significant digits of the decimal exponent tinyobjloader's own number parser reads in
// `token` (its tryParseDouble: [sign] digits [. digits] [e|E [sign] digits], or a leading
// '.'), leading zeros not counted; 0 when it reads none. It sums the exponent in an int,
// which 10 digits overflow.
size_t tinyobjExponentDigits(std::string_view token) {
  const auto digit = [&](size_t k) {
    return k < token.size() && token[k] >= '0' && token[k] <= '9';
  };
  size_t i = 0;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  if (!digit(i) && !(i < token.size() && token[i] == '.')) return 0;
  while (digit(i)) ++i;
  if (i < token.size() && token[i] == '.') {
    for (++i; digit(i);) ++i;
  }
  if (i >= token.size() || (token[i] != 'e' && token[i] != 'E')) return 0;
  ++i;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  while (i < token.size() && token[i] == '0') ++i;
  size_t digits = 0;
  while (digit(i + digits)) ++digits;
  return digits;
}

// Exponents of more digits are refused: the number is 0 or beyond float range anyway.
constexpr size_t kMaxExponentDigits = 4;

class ObjScanner {
 public:
  explicit ObjScanner(const std::string& source) : source_(source) {}

  void scanLine(std::string_view line, uint32_t line_number) {
    line_ = line_number;
    const auto tokens = splitTokens(line);
    if (tokens.empty() || tokens[0][0] == '#') return;
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      scanCoordinates(tokens, 3, "vertex position");
      // tinyobjloader reads three more numbers as a colour when there are.
      for (size_t i = 4; i < tokens.size() && i <= 6; ++i) checkExponent(tokens[i], "vertex");
      ++position_count_;
    } else if (keyword == "vn") {
      scanCoordinates(tokens, 3, "vertex normal");
      ++normal_count_;
    } else if (keyword == "vt") {
      scanCoordinates(tokens, 2, "texture coordinate");
      ++uv_count_;
    } else if (keyword == "f") {
      scanFace(tokens);
    } else if (keyword == "t") {
      tag_lines_.push_back({std::string(line), line_number});
    } else if (keyword == "vw") {
      scanSkinWeights(tokens);
    }
  }

  std::vector<uint32_t> takeFaceLines() { return std::move(face_lines_); }

  // Tags may name vertices and faces defined after them, so check them last.
  void finish() {
    line_ = 0;
    if (face_count_ == 0) fail("", "has no faces (empty or not an OBJ mesh)");
    for (const auto& [text, number] : tag_lines_) {
      line_ = number;
      scanTag(splitTokens(text));
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what, const std::string& rule) const {
    const std::string element = line_ ? "line " + std::to_string(line_) : "";
    throw InputError(source_, element, what.empty() ? rule : what + " " + rule);
  }

  void scanCoordinates(const std::vector<std::string_view>& tokens, size_t needed,
                       const char* what) {
    if (tokens.size() < needed + 1) {
      fail(what, "needs " + std::to_string(needed) + " numbers, has " +
                     std::to_string(tokens.size() - 1));
    }
    for (size_t i = 1; i <= needed; ++i) {
      double value = 0;
      if (!parseDouble(tokens[i], &value)) {
        fail(what, "has a non-number '" + std::string(tokens[i]) + "'");
      }
      if (!std::isfinite(value)) {
        fail(what, "is not finite ('" + std::string(tokens[i]) + "'): NaN and Inf are rejected");
      }
      if (!fitsFloat(value)) {
        fail(what, "is beyond float range ('" + std::string(tokens[i]) +
                       "'): coordinates are read as 32-bit floats");
      }
      checkExponent(tokens[i], what);
    }
  }

  // A token tinyobjloader parses as a number must not overflow its exponent sum.
  void checkExponent(std::string_view token, const std::string& what) {
    if (tinyobjExponentDigits(token) > kMaxExponentDigits) {
      fail(what, "has an exponent of more than " + std::to_string(kMaxExponentDigits) +
                     " digits ('" + std::string(token) + "')");
    }
  }

  // tinyobjloader's skin weights, "vw <vertex> <joint> <weight> ...": unused here, but
  // tinyobjloader reads each joint as a float and converts it to int, which must not
  // overflow; whole numbers up to 2^24 are exact floats (2147483647 rounds to 2^31).
  void scanSkinWeights(const std::vector<std::string_view>& tokens) {
    constexpr long kMaxJoint = 1L << 24;
    long value = 0;
    if (tokens.size() < 2 || !parseInt(tokens[1], &value) || tokens.size() % 2 != 0) {
      fail("vertex weight", "needs a vertex index and joint-weight pairs");
    }
    for (size_t i = 2; i < tokens.size(); i += 2) {
      if (!parseInt(tokens[i], &value) || value < 0 || value > kMaxJoint) {
        fail("vertex weight", "has a joint '" + std::string(tokens[i]) +
                                  "' that is not a whole number in 0.." +
                                  std::to_string(kMaxJoint));
      }
      double weight = 0;
      if (!parseDouble(tokens[i + 1], &weight) || !std::isfinite(weight) || !fitsFloat(weight)) {
        fail("vertex weight", "has a weight '" + std::string(tokens[i + 1]) +
                                  "' that is not a finite number in float range");
      }
      checkExponent(tokens[i + 1], "vertex weight");
    }
  }

  // Resolves a 1-based or negative (relative) OBJ index to 0-based; fails when out of range.
  long checkIndex(std::string_view token, long count, const char* what) {
    long index = 0;
    if (!parseInt(token, &index)) {
      fail("face", "has a malformed " + std::string(what) + " index '" + std::string(token) + "'");
    }
    const long resolved = index < 0 ? count + index : index - 1;
    if (index == 0 || resolved < 0 || resolved >= count) {
      fail("face", std::string(what) + " index " + std::to_string(index) + " is out of range (1.." +
                       std::to_string(count) + " defined so far)");
    }
    return resolved;
  }

  void scanFace(const std::vector<std::string_view>& tokens) {
    if (tokens.size() < 4) {
      fail("face", "has " + std::to_string(tokens.size() - 1) +
                       " vertices; a face needs at least 3 (degenerate face)");
    }
    if (tokens.size() - 1 > kMaxFaceCorners) {
      fail("face", "has " + std::to_string(tokens.size() - 1) + " vertices; at most " +
                       std::to_string(kMaxFaceCorners) + " are supported");
    }
    std::vector<long> vertices;
    for (size_t i = 1; i < tokens.size(); ++i) {
      std::string_view corner = tokens[i];
      // "2/" or "2//": tinyobjloader takes the next corner's number (atoi skips the space)
      // for the missing index.
      if (corner.back() == '/') {
        fail("face", "has a corner '" + std::string(corner) +
                         "' ending in '/' (an index must follow every '/')");
      }
      const size_t slash1 = corner.find('/');
      const long vertex = checkIndex(corner.substr(0, slash1), position_count_, "vertex");
      // A corner repeated anywhere in the face (f 1 2 2) collapses an edge: no patch or
      // normal is defined on it.
      if (std::find(vertices.begin(), vertices.end(), vertex) != vertices.end()) {
        fail("face", "uses vertex " + std::to_string(vertex + 1) + " twice (degenerate face)");
      }
      vertices.push_back(vertex);
      if (slash1 == std::string_view::npos) continue;
      std::string_view rest = corner.substr(slash1 + 1);
      const size_t slash2 = rest.find('/');
      const std::string_view uv = rest.substr(0, slash2);
      if (!uv.empty()) checkIndex(uv, uv_count_, "texture coordinate");
      if (slash2 != std::string_view::npos) {
        const std::string_view normal = rest.substr(slash2 + 1);
        if (!normal.empty()) checkIndex(normal, normal_count_, "normal");
      }
    }
    ++face_count_;
    face_lines_.push_back(line_);
  }

  void scanTag(const std::vector<std::string_view>& tokens) {
    if (tokens.size() < 3) fail("tag", "needs a name and an int/float/string count triple");
    const std::string name(tokens[1]);
    long counts[3] = {0, 0, 0};
    std::string_view triple = tokens[2];
    for (int k = 0; k < 3; ++k) {
      const size_t slash = triple.find('/');
      if (!parseInt(triple.substr(0, slash), &counts[k]) || counts[k] < 0) {
        fail("tag '" + name + "'",
             "has an unreadable count triple '" + std::string(tokens[2]) + "'");
      }
      if (k < 2 && slash == std::string_view::npos) {
        fail("tag '" + name + "'",
             "has an unreadable count triple '" + std::string(tokens[2]) + "'");
      }
      triple = slash == std::string_view::npos ? std::string_view() : triple.substr(slash + 1);
    }
    // Each count is bounded before they are summed: three huge counts would overflow.
    const size_t given = tokens.size() - 3;
    for (long count : counts) {
      if (size_t(count) > given) {
        fail("tag '" + name + "'",
             "declares " + std::to_string(count) + " values but has " + std::to_string(given));
      }
    }
    const size_t declared = size_t(counts[0] + counts[1] + counts[2]);
    if (declared != given) {
      fail("tag '" + name + "'",
           "declares " + std::to_string(declared) + " values but has " + std::to_string(given));
    }
    std::vector<long> ints(counts[0]);
    for (long k = 0; k < counts[0]; ++k) {
      if (!parseInt(tokens[3 + k], &ints[k])) {
        fail("tag '" + name + "'", "has a non-integer '" + std::string(tokens[3 + k]) + "'");
      }
    }
    for (long k = 0; k < counts[1]; ++k) {
      double value = 0;
      const auto token = tokens[3 + counts[0] + k];
      if (!parseDouble(token, &value) || !std::isfinite(value)) {
        fail("tag '" + name + "'", "has a non-number '" + std::string(token) + "'");
      }
      if (!fitsFloat(value)) {
        fail("tag '" + name + "'", "has '" + std::string(token) +
                                       "', beyond float range (tag values are read as floats)");
      }
      checkExponent(token, "tag '" + name + "'");
    }
    checkTagReferences(name, ints);
  }

  void checkTagReferences(const std::string& name, const std::vector<long>& ints) {
    long limit = -1;
    const char* what = "";
    if (name == "crease" || name == "corner") {
      limit = position_count_;
      what = "vertex";
    } else if (name == "hole") {
      limit = face_count_;
      what = "face";
    }
    if (name == "crease" && ints.size() % 2 != 0) {
      fail("tag 'crease'", "needs vertex pairs, has " + std::to_string(ints.size()) + " ints");
    }
    for (long id : ints) {
      if (limit >= 0 && (id < 0 || id >= limit)) {
        fail("tag '" + name + "'", std::string(what) + " " + std::to_string(id) +
                                       " is out of range (0.." + std::to_string(limit - 1) + ")");
      }
    }
  }

  const std::string& source_;
  uint32_t line_ = 0;
  long position_count_ = 0, normal_count_ = 0, uv_count_ = 0, face_count_ = 0;
  std::vector<std::pair<std::string, uint32_t>> tag_lines_;
  std::vector<uint32_t> face_lines_;
};

}  // namespace

std::vector<uint32_t> validateObjText(std::string_view text, const std::string& source_name) {
  ObjScanner scanner(source_name);
  uint32_t line_number = 0;
  size_t start = 0;
  while (start <= text.size()) {
    // A line ends at \n, \r\n or a lone \r, as tinyobjloader splits them (safeGetline): a
    // lone \r taken for a space would let the scan count vertices and faces that
    // tinyobjloader reads differently, and faces index past the positions.
    size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    ++line_number;
    scanner.scanLine(text.substr(start, end - start), line_number);
    start = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
  }
  scanner.finish();
  return scanner.takeFaceLines();
}

}  // namespace tb::mesh
