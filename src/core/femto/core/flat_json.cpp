#include <femto/core/flat_json.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <femto/base/error.h>

namespace femto {
namespace {

/// Recursive-descent reader over the text; `fail` names the line of the cursor.
class Reader {
 public:
  Reader(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  FlatJson object() {
    FlatJson result;
    expect('{');
    if (peek() == '}') return ++pos_, finish(result);
    for (;;) {
      std::string key = string();
      expect(':');
      result[key] = value();
      char c = next();
      if (c == '}') return finish(result);
      if (c != ',') fail("expected ',' or '}' after a value");
    }
  }

 private:
  FlatJson finish(FlatJson& result) {
    if (peek() != '\0') fail("unexpected text after the object");
    return std::move(result);
  }

  FlatJsonValue value() {
    char c = peek();
    if (c == '"') return string();
    if (c == '[') return numbers();
    if (c == '{') fail("nested objects are not supported here");
    if (word("true")) return true;
    if (word("false")) return false;
    if (word("null")) return nullptr;
    return number();
  }

  std::vector<double> numbers() {
    std::vector<double> list;
    expect('[');
    if (peek() == ']') return ++pos_, list;
    for (;;) {
      list.push_back(number());
      char c = next();
      if (c == ']') return list;
      if (c != ',') fail("expected ',' or ']' in an array of numbers");
    }
  }

  double number() {
    skipSpace();
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    double v = std::strtod(begin, &end);
    if (end == begin) fail("expected a value");
    pos_ += size_t(end - begin);
    return v;
  }

  std::string string() {
    expect('"');
    std::string s;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      char c = text_[pos_++];
      if (c == '\\') {
        if (pos_ >= text_.size()) break;
        char e = text_[pos_++];
        switch (e) {
          case 'n': s += '\n'; break;
          case 't': s += '\t'; break;
          case 'r': s += '\r'; break;
          case 'b': s += '\b'; break;
          case 'f': s += '\f'; break;
          case 'u': fail("\\u escapes are not supported here");
          default: s += e;  // \" \\ \/
        }
      } else {
        s += c;
      }
    }
    if (pos_ >= text_.size()) fail("unterminated string");
    ++pos_;
    return s;
  }

  bool word(const char* w) {
    skipSpace();
    size_t n = std::char_traits<char>::length(w);
    if (text_.compare(pos_, n, w) != 0) return false;
    pos_ += n;
    return true;
  }
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  char peek() {
    skipSpace();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  char next() {
    char c = peek();
    if (c != '\0') ++pos_;
    return c;
  }
  void expect(char c) {
    if (next() != c) fail(str("expected '", c, "'"));
  }
  [[noreturn]] void fail(const std::string& what) const {
    int line = 1;
    for (size_t i = 0; i < pos_ && i < text_.size(); ++i) line += text_[i] == '\n';
    throw Error(SourceLocation{source_, line}, str("invalid JSON: ", what));
  }

  const std::string& text_;
  const std::string& source_;
  size_t pos_ = 0;
};

}  // namespace

FlatJson parseFlatJson(const std::string& text, const std::string& source) { return Reader(text, source).object(); }

std::string jsonQuote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", unsigned(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), v);  // shortest text that reads back exactly
  (void)ec;  // 32 chars always suffice for a double
  return std::string(buf, end);
}

}  // namespace femto
