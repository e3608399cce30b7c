#include "spira/io/ply_header.h"

#include <charconv>
#include <optional>

#include "spira/base/error.h"

namespace spira {
namespace {

const char* const kHeaderHint = "the PLY header is malformed; export the part again as PLY (ASCII or binary)";

struct TypeName {
  std::string_view name;
  PlyType type;
};

constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},       {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},     {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},   {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},   {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

std::optional<PlyType> typeNamed(std::string_view name)
{
  for (const TypeName& t : kTypeNames)
    if (t.name == name) return t.type;
  return std::nullopt;
}

std::vector<std::string_view> words(std::string_view line)
{
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > begin) out.push_back(line.substr(begin, i - begin));
  }
  return out;
}

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  PlyHeader parse()
  {
    const std::string_view magic = nextLine();
    if (magic != "ply")
      throw InputError("'" + source_ + "' is not a PLY file: it does not start with the line 'ply'",
                       "choose a PLY file, or give the file the extension of its real format");
    bool formatSeen = false;
    for (;;) {
      if (pos_ >= bytes_.size() || pos_ >= kMaxPlyHeaderBytes) missingEnd();
      const std::string_view line = nextLine();
      if (!complete_) missingEnd();  // a header cut inside a line is a header without end_header
      const std::vector<std::string_view> w = words(line);
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "end_header") break;
      if (w[0] == "format") {
        if (formatSeen) fail("a second 'format' line");
        format(w);
        formatSeen = true;
      } else if (w[0] == "element") {
        if (!formatSeen) fail("an 'element' line before the 'format' line");
        element(w);
      } else if (w[0] == "property") {
        if (header_.elements.empty()) fail("a 'property' line before any 'element' line");
        property(w);
      } else {
        const bool data = std::string_view("0123456789+-.").find(w[0][0]) != std::string_view::npos;
        fail("'" + plyExcerpt(w[0]) + "', which is not a PLY header keyword" +
             (data ? " (the 'end_header' line is missing before the data)" : ""));
      }
    }
    if (!formatSeen) fail("'end_header' before any 'format' line");
    header_.bodyOffset = pos_;
    header_.lines = line_;
    return header_;
  }

 private:
  // The next '\n'-terminated line without its terminator (and without a '\r' before it).
  std::string_view nextLine()
  {
    const size_t end = bytes_.find('\n', pos_);
    complete_ = end != std::string_view::npos;
    std::string_view line = bytes_.substr(pos_, complete_ ? end - pos_ : std::string_view::npos);
    pos_ = complete_ ? end + 1 : bytes_.size();
    ++line_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }

  void format(const std::vector<std::string_view>& w)
  {
    if (w.size() != 3) fail("a format line that is not 'format <encoding> 1.0'");
    if (w[1] == "ascii")
      header_.encoding = PlyEncoding::Ascii;
    else if (w[1] == "binary_little_endian")
      header_.encoding = PlyEncoding::BinaryLittleEndian;
    else if (w[1] == "binary_big_endian")
      header_.encoding = PlyEncoding::BinaryBigEndian;
    else
      fail("the format '" + plyExcerpt(w[1]) + "', not ascii, binary_little_endian or binary_big_endian");
    if (w[2] != "1.0" && w[2] != "1") fail("PLY version '" + plyExcerpt(w[2]) + "'; Spira reads version 1.0");
  }

  void element(const std::vector<std::string_view>& w)
  {
    if (w.size() != 3) fail("an element line that is not 'element <name> <count>'");
    PlyElement e;
    e.name = std::string(w[1]);
    e.line = line_;
    const auto r = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
    if (r.ec != std::errc() || r.ptr != w[2].data() + w[2].size())
      fail("the count '" + plyExcerpt(w[2]) + "' of element '" + plyExcerpt(w[1]) +
           "', which is not a whole number of at most 2^64 - 1");
    for (const PlyElement& other : header_.elements)
      if (other.name == e.name) fail("a second element named '" + plyExcerpt(w[1]) + "'");
    header_.elements.push_back(std::move(e));
  }

  void property(const std::vector<std::string_view>& w)
  {
    PlyProperty p;
    if (w.size() >= 2 && w[1] == "list") {
      if (w.size() != 5) fail("a list property that is not 'property list <count type> <item type> <name>'");
      p.isList = true;
      p.countType = typeOf(w[2]);
      if (!plyTypeIsInteger(p.countType))
        fail("a list whose count type is '" + plyExcerpt(w[2]) + "'; counts must have an integer type");
      p.type = typeOf(w[3]);
      p.name = std::string(w[4]);
    } else {
      if (w.size() != 3) fail("a property line that is not 'property <type> <name>'");
      p.type = typeOf(w[1]);
      p.name = std::string(w[2]);
    }
    PlyElement& e = header_.elements.back();
    if (e.find(p.name) >= 0)
      fail("a second property '" + plyExcerpt(p.name) + "' in element '" + plyExcerpt(e.name) + "'");
    e.properties.push_back(std::move(p));
  }

  PlyType typeOf(std::string_view name) const
  {
    if (auto t = typeNamed(name)) return *t;
    fail("the type '" + plyExcerpt(name) +
         "', not one of char, uchar, short, ushort, int, uint, float, double (or int8 ... float64)");
  }

  [[noreturn]] void fail(const std::string& found) const
  {
    throw InputError("'" + source_ + "' line " + std::to_string(line_) + ": the PLY header has " + found,
                     kHeaderHint);
  }

  [[noreturn]] void missingEnd() const
  {
    const bool tooLong = pos_ >= kMaxPlyHeaderBytes && bytes_.size() > kMaxPlyHeaderBytes;
    throw InputError("'" + source_ + "': the PLY header has no 'end_header' line " +
                         (tooLong ? "in its first " + std::to_string(kMaxPlyHeaderBytes) + " bytes"
                                  : "before the file ends (line " + std::to_string(line_) + ")"),
                     "the file is truncated or not a PLY file; export the part again");
  }

  std::string_view bytes_;
  const std::string& source_;
  PlyHeader header_;
  size_t pos_ = 0;
  size_t line_ = 0;
  bool complete_ = true;
};

}  // namespace

size_t plyTypeSize(PlyType type)
{
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool plyTypeIsInteger(PlyType type)
{
  return type != PlyType::Float32 && type != PlyType::Float64;
}

int PlyElement::find(std::string_view propertyName) const
{
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == propertyName) return static_cast<int>(i);
  return -1;
}

std::uint64_t PlyElement::minBinaryBytes() const
{
  std::uint64_t bytes = 0;
  for (const PlyProperty& p : properties) bytes += plyTypeSize(p.isList ? p.countType : p.type);
  return bytes;
}

std::string plyExcerpt(std::string_view text)
{
  std::string shown(text.substr(0, 40));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
  return shown;
}

PlyHeader parsePlyHeader(std::string_view bytes, const std::string& source)
{
  return HeaderParser(bytes, source).parse();
}

}  // namespace spira
