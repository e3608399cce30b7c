#include "spira/io/json_read.h"

#include <cmath>

#include "spira/base/error.h"

namespace spira::json_read {

namespace {

using nlohmann::json;

constexpr size_t kQuoteChars = 60;

std::string clip(const std::string& s)
{
  return s.size() <= kQuoteChars ? s : s.substr(0, kQuoteChars) + "...";
}

std::string lineAndColumn(const std::string& text, size_t offset)
{
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Builds the document as the library does, but turns its errors (which carry the position only
// through this interface) into InputErrors with line and column.
class LocatingParser : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  LocatingParser(json& result, const std::string& text, const std::string& what, const std::string& hint)
      : json_sax_dom_parser(result, true), text_(text), what_(what), hint_(hint)
  {
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex)
  {
    const size_t start = position >= token.size() ? position - token.size() : 0;
    const std::string where = what_ + ", " + lineAndColumn(text_, start) + ": ";
    if (ex.id == 406)
      throw InputError(where + "the number " + clip(token) + " is beyond the range of a double", hint_);
    if (token.empty() || position >= text_.size())
      throw InputError(what_ + ", " + lineAndColumn(text_, text_.size()) + ": the JSON text ends too early",
                       hint_);
    throw InputError(where + "unexpected '" + clip(token) + "' (not valid JSON)", hint_);
  }

 private:
  const std::string& text_;
  const std::string& what_;
  const std::string& hint_;
};

// The CBOR decoder descends one call per nesting level: deeper data is refused before it can
// overflow the stack. Spira's own files nest a few levels.
constexpr size_t kMaxCborDepth = 64;

class BoundedCborParser : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  BoundedCborParser(json& result, const std::string& what, const std::string& hint)
      : json_sax_dom_parser(result, true), what_(what), hint_(hint)
  {
  }

  bool start_object(std::size_t n)
  {
    enter();
    return json_sax_dom_parser::start_object(n);
  }
  bool end_object()
  {
    --depth_;
    return json_sax_dom_parser::end_object();
  }
  bool start_array(std::size_t n)
  {
    enter();
    return json_sax_dom_parser::start_array(n);
  }
  bool end_array()
  {
    --depth_;
    return json_sax_dom_parser::end_array();
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string&, const Exception&)
  {
    throw InputError(what_ + ": the binary content is malformed at byte " + std::to_string(position), hint_);
  }

 private:
  void enter()
  {
    if (++depth_ > kMaxCborDepth)
      throw InputError(what_ + ": the content nests deeper than " + std::to_string(kMaxCborDepth) + " levels",
                       hint_);
  }
  size_t depth_ = 0;
  const std::string& what_;
  const std::string& hint_;
};

[[noreturn]] void wrongType(const char* key, const char* expected, const json& found, const std::string& what,
                            const std::string& hint)
{
  throw InputError(what + ": field '" + key + "' must be " + expected + ", found " + describe(found), hint);
}

bool isWhole(const json& v)
{
  if (v.is_number_integer()) return true;
  if (!v.is_number_float()) return false;
  const double x = v.get<double>();
  return std::isfinite(x) && std::floor(x) == x && std::abs(x) < 9.2e18;
}

}  // namespace

json parse(const std::string& text, const std::string& what, const std::string& hint)
{
  json result;
  LocatingParser parser(result, text, what, hint);
  json::sax_parse(text, &parser);
  return result;
}

json parseCbor(std::string_view bytes, const std::string& what, const std::string& hint)
{
  json result;
  BoundedCborParser parser(result, what, hint);
  try {
    json::sax_parse(bytes.begin(), bytes.end(), &parser, json::input_format_t::cbor);
  } catch (const json::exception&) {
    // The decoder throws directly, not through parse_error, for a declared size beyond any memory.
    throw InputError(what + ": the binary content declares a size it cannot hold", hint);
  }
  return result;
}

std::string describe(const json& v)
{
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case json::value_t::string:
      return "the string \"" + clip(v.get<std::string>()) + "\"";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "the number " + clip(v.dump());
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "a list";
    default:
      return "binary data";
  }
}

const json& member(const json& object, const char* key, const std::string& what, const std::string& hint)
{
  if (!object.is_object()) throw InputError(what + ": expected an object, found " + describe(object), hint);
  const auto it = object.find(key);
  if (it == object.end()) throw InputError(what + ": field '" + std::string(key) + "' is missing", hint);
  return *it;
}

std::string text(const json& object, const char* key, const std::string& what, const std::string& hint)
{
  const json& v = member(object, key, what, hint);
  if (!v.is_string()) wrongType(key, "a string", v, what, hint);
  return v.get<std::string>();
}

double number(const json& object, const char* key, const std::string& what, const std::string& hint)
{
  const json& v = member(object, key, what, hint);
  if (!v.is_number()) wrongType(key, "a number", v, what, hint);
  return v.get<double>();
}

std::int64_t wholeNumber(const json& object, const char* key, const std::string& what,
                         const std::string& hint)
{
  const json& v = member(object, key, what, hint);
  if (!isWhole(v)) wrongType(key, "a whole number", v, what, hint);
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
    wrongType(key, "a whole number below 2^63", v, what, hint);
  return v.is_number_float() ? static_cast<std::int64_t>(v.get<double>()) : v.get<std::int64_t>();
}

bool flag(const json& object, const char* key, const std::string& what, const std::string& hint)
{
  const json& v = member(object, key, what, hint);
  if (!v.is_boolean()) wrongType(key, "true or false", v, what, hint);
  return v.get<bool>();
}

std::string text(const json& object, const char* key, const std::string& fallback, const std::string& what,
                 const std::string& hint)
{
  return object.is_object() && object.contains(key) ? text(object, key, what, hint) : fallback;
}

double number(const json& object, const char* key, double fallback, const std::string& what,
              const std::string& hint)
{
  return object.is_object() && object.contains(key) ? number(object, key, what, hint) : fallback;
}

std::int64_t wholeNumber(const json& object, const char* key, std::int64_t fallback, const std::string& what,
                         const std::string& hint)
{
  return object.is_object() && object.contains(key) ? wholeNumber(object, key, what, hint) : fallback;
}

}  // namespace spira::json_read
