#pragma once

// The two ways a PLY body is walked, value by value: binary (either byte order) and ASCII (one
// item per line). Both have the same members so one template reads the elements; both report
// problems as PlyBodyProblem and leave the sentence to the reader, which knows the element and item.

#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "spira/base/number_text.h"
#include "spira/io/ply_header.h"

namespace spira::ply_detail {

struct PlyBodyProblem {
  enum Kind {
    End,        // the file ends inside an item
    ShortItem,  // an ASCII line ends before the item's last value
    LongItem,   // an ASCII line holds more values than the item declares
    NotNumber,  // an ASCII value is not a number
    NotWhole,   // an ASCII count or index is not a whole number
  };
  Kind kind;
  std::string found;  // the offending text, made printable
};

template <bool BigEndian>
class BinaryCursor {
 public:
  BinaryCursor(std::string_view bytes, size_t pos) : bytes_(bytes), pos_(pos) {}

  void beginItem() {}
  void endItem() {}
  size_t position() const { return pos_; }
  std::string where() const { return "byte " + std::to_string(pos_); }

  double real(PlyType type) { return value<double>(type); }

  // Counts and corner indices: the header gives them integer types only.
  std::int64_t whole(PlyType type) { return plyTypeIsInteger(type) ? value<std::int64_t>(type) : -1; }

  void skip(PlyType type) { advance(plyTypeSize(type)); }

  void skipList(std::uint64_t count, PlyType type)
  {
    const std::uint64_t left = bytes_.size() - pos_;
    if (count > left / plyTypeSize(type)) throw PlyBodyProblem{PlyBodyProblem::End, {}};
    pos_ += static_cast<size_t>(count * plyTypeSize(type));
  }

 private:
  void advance(size_t n)
  {
    if (bytes_.size() - pos_ < n) throw PlyBodyProblem{PlyBodyProblem::End, {}};
    pos_ += n;
  }

  template <class R>
  R value(PlyType type)
  {
    switch (type) {
      case PlyType::Int8:
        return static_cast<R>(load<std::int8_t>());
      case PlyType::UInt8:
        return static_cast<R>(load<std::uint8_t>());
      case PlyType::Int16:
        return static_cast<R>(load<std::int16_t>());
      case PlyType::UInt16:
        return static_cast<R>(load<std::uint16_t>());
      case PlyType::Int32:
        return static_cast<R>(load<std::int32_t>());
      case PlyType::UInt32:
        return static_cast<R>(load<std::uint32_t>());
      case PlyType::Float32:
        return static_cast<R>(load<float>());
      case PlyType::Float64:
        return static_cast<R>(load<double>());
    }
    return R{};
  }

  template <class T>
  T load()
  {
    const size_t at = pos_;
    advance(sizeof(T));
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + at, sizeof(T));
    const bool hostBig = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
    if (hostBig != BigEndian)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string_view bytes_;
  size_t pos_;
};

class AsciiCursor {
 public:
  AsciiCursor(std::string_view text, size_t pos, size_t line) : text_(text), pos_(pos), line_(line) {}

  size_t position() const { return pos_; }
  std::string where() const { return "line " + std::to_string(line_); }

  // Blank lines between items are allowed; the file ending here is not.
  void beginItem()
  {
    skipBlank();
    if (pos_ == text_.size()) throw PlyBodyProblem{PlyBodyProblem::End, {}};
  }

  void endItem()
  {
    skipSpaces();
    if (pos_ < text_.size() && text_[pos_] != '\n') {
      const size_t end = text_.find_first_of(" \t\r\n", pos_);
      throw PlyBodyProblem{PlyBodyProblem::LongItem, plyExcerpt(text_.substr(pos_, end - pos_))};
    }
  }

  double real(PlyType)
  {
    const std::string_view t = token();
    const std::optional<double> value = parseMeshNumber(t);
    if (!value) throw PlyBodyProblem{PlyBodyProblem::NotNumber, plyExcerpt(t)};
    return *value;
  }

  std::int64_t whole(PlyType)
  {
    const std::string_view t = token();
    std::string_view digits = t;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    std::int64_t value = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (r.ec != std::errc() || r.ptr != digits.data() + digits.size())
      throw PlyBodyProblem{PlyBodyProblem::NotWhole, plyExcerpt(t)};
    return value;
  }

  void skip(PlyType type) { real(type); }

  void skipList(std::uint64_t count, PlyType type)
  {
    for (std::uint64_t i = 0; i < count; ++i) skip(type);
  }

  // Whether anything but white space follows the last element.
  bool restIsBlank()
  {
    skipBlank();
    return pos_ == text_.size();
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  void skipSpaces()
  {
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
  }

  void skipBlank()
  {
    for (; pos_ < text_.size() && (isSpace(text_[pos_]) || text_[pos_] == '\n'); ++pos_)
      if (text_[pos_] == '\n') ++line_;
  }

  // The next value on the item's line.
  std::string_view token()
  {
    skipSpaces();
    if (pos_ == text_.size()) throw PlyBodyProblem{PlyBodyProblem::End, {}};
    if (text_[pos_] == '\n') throw PlyBodyProblem{PlyBodyProblem::ShortItem, {}};
    const size_t begin = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    return text_.substr(begin, pos_ - begin);
  }

  std::string_view text_;
  size_t pos_;
  size_t line_;
};

}  // namespace spira::ply_detail
