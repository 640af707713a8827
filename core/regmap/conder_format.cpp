#include "regmap/conder_format.h"

#include <cctype>

#include "base/error.h"

namespace tessera::regmap {

namespace {

// A read position in a text that knows its line and column; every read is bounds-checked, so no
// input can make the parser look past the end of its buffer.
class Cursor {
 public:
  Cursor(std::string_view text, TextOrigin origin)
      : text_(text),
        source_(std::move(origin.source)),
        line_(origin.line),
        column_(origin.column) {}

  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  bool peek_is(char c) const { return !at_end() && text_[pos_] == c; }

  void advance() {
    if (at_end()) return;
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  void skip_blanks() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\r')) advance();
  }

  void skip_whitespace() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(peek()))) advance();
  }

  bool accept(char c) {
    if (!peek_is(c)) return false;
    advance();
    return true;
  }

  bool accept_word(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    for (std::size_t i = 0; i < word.size(); ++i) advance();
    return true;
  }

  void expect(char c, const std::string& context) {
    if (!accept(c)) fail("expected '" + std::string(1, c) + "' " + context + ", found " + found());
  }

  // A non-negative decimal number no larger than `cap`.
  long long number(long long cap, const std::string& what) {
    if (!std::isdigit(static_cast<unsigned char>(peek())))
      fail("expected " + what + " (a number), found " + found());
    long long value = 0;
    while (std::isdigit(static_cast<unsigned char>(peek()))) {
      value = value * 10 + (peek() - '0');
      if (value > cap) fail(what + " is larger than " + std::to_string(cap));
      advance();
    }
    return value;
  }

  std::string found() const {
    if (at_end()) return "the end of the text";
    const unsigned char c = static_cast<unsigned char>(peek());
    if (!std::isprint(c)) return "byte " + std::to_string(c);
    std::string quoted = "'";
    quoted += static_cast<char>(c);
    quoted += '\'';
    return quoted;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(source_ + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " +
                     what);
  }

  std::size_t offset() const { return pos_; }
  std::string_view rest() const { return text_.substr(pos_); }

 private:
  std::string_view text_;
  std::string source_;
  std::size_t line_, column_;
  std::size_t pos_ = 0;
};

// Recursive descent over: product := factor ('*' factor)*; factor := atom ('^' ['-'] int)?;
// atom := R | S | T | '(' product ')'. Nesting depth is capped so that the recursion stays
// shallow whatever the input.
class RelatorParser {
 public:
  explicit RelatorParser(Cursor& cursor) : cursor_(cursor) {}

  Word product() {
    Word word = factor();
    cursor_.skip_whitespace();
    while (cursor_.accept('*')) {
      append(word, factor());
      cursor_.skip_whitespace();
    }
    return word;
  }

 private:
  static constexpr int kMaxNesting = 64;

  Word factor() {
    Word base = atom();
    cursor_.skip_whitespace();
    if (!cursor_.accept('^')) return base;
    cursor_.skip_whitespace();
    const bool negative = cursor_.accept('-');
    const long long exponent = cursor_.number(kMaxExponent, "the exponent");
    if (!base.empty() && static_cast<std::size_t>(exponent) > kMaxRelatorLetters / base.size())
      cursor_.fail("the power expands to more than " + std::to_string(kMaxRelatorLetters) +
                   " letters; write the relator with smaller exponents");
    return power(base, static_cast<int>(negative ? -exponent : exponent));
  }

  Word atom() {
    cursor_.skip_whitespace();
    if (cursor_.accept('(')) {
      if (++depth_ > kMaxNesting)
        cursor_.fail("parentheses nested deeper than " + std::to_string(kMaxNesting));
      Word inner = product();
      cursor_.skip_whitespace();
      if (!cursor_.accept(')'))
        cursor_.fail("expected ')' to close a parenthesis, found " + cursor_.found() +
                     " (unbalanced parentheses)");
      --depth_;
      return inner;
    }
    switch (cursor_.peek()) {
      case 'R':
        cursor_.advance();
        return {Letter::R};
      case 'S':
        cursor_.advance();
        return {Letter::S};
      case 'T':
        cursor_.advance();
        return {Letter::T};
      default:
        break;
    }
    if (std::isalpha(static_cast<unsigned char>(cursor_.peek())))
      cursor_.fail("unknown generator " + cursor_.found() + "; the generators are R, S and T");
    cursor_.fail("expected a generator (R, S, T) or '(', found " + cursor_.found());
  }

  void append(Word& word, const Word& tail) {
    if (word.size() + tail.size() > kMaxRelatorLetters)
      cursor_.fail("the relator expands to more than " + std::to_string(kMaxRelatorLetters) +
                   " letters; write it with smaller exponents");
    word.insert(word.end(), tail.begin(), tail.end());
  }

  Cursor& cursor_;
  int depth_ = 0;
};

std::vector<Word> parse_relators_at(Cursor& cursor) {
  cursor.skip_whitespace();
  if (cursor.at_end()) cursor.fail("expected a relator list '[ ... ]', found nothing");
  cursor.expect('[', "to open the relator list");
  std::vector<Word> relators;
  cursor.skip_whitespace();
  if (cursor.accept(']')) cursor.fail("the relator list is empty");
  for (;;) {
    RelatorParser parser(cursor);
    relators.push_back(parser.product());
    cursor.skip_whitespace();
    if (cursor.accept(']')) return relators;
    if (cursor.peek_is(')')) cursor.fail("unexpected ')' (unbalanced parentheses)");
    if (!cursor.accept(','))
      cursor.fail("expected ',' or ']' after a relator, found " + cursor.found());
  }
}

void expect_only_whitespace(Cursor& cursor, const std::string& what) {
  cursor.skip_whitespace();
  if (!cursor.at_end()) cursor.fail("unexpected " + cursor.found() + " after " + what);
}

// "R97.10 :" (optional) -> the name, or "" when the header starts with "Type".
std::string parse_name(Cursor& cursor) {
  cursor.skip_whitespace();
  if (cursor.rest().substr(0, 4) == "Type") return "";
  std::string name;
  while (!cursor.at_end() && !cursor.peek_is(':') &&
         !std::isspace(static_cast<unsigned char>(cursor.peek()))) {
    name += cursor.peek();
    cursor.advance();
  }
  cursor.skip_blanks();
  if (!cursor.accept(':'))
    cursor.fail(
        "missing type: expected 'Rg.n : Type {p,q}' or 'Type {p,q}' (e.g. 'R3.1 : Type "
        "{3,7}_8'), found " +
        cursor.found());
  return name;
}

// "Type {p,q}_r" -> p, q and (optionally) r into the presentation.
void parse_type(Cursor& cursor, Presentation& presentation) {
  cursor.skip_whitespace();
  if (!cursor.accept_word("Type"))
    cursor.fail("missing type: expected 'Type {p,q}' (e.g. 'Type {3,7}_8'), found " +
                cursor.found());
  cursor.skip_blanks();
  cursor.expect('{', "to open the type {p,q}");
  cursor.skip_blanks();
  presentation.p = static_cast<int>(cursor.number(kMaxValence, "p in {p,q}"));
  cursor.skip_blanks();
  cursor.expect(',', "between p and q in {p,q}");
  cursor.skip_blanks();
  presentation.q = static_cast<int>(cursor.number(kMaxValence, "q in {p,q}"));
  cursor.skip_blanks();
  cursor.expect('}', "to close the type {p,q}");
  if (presentation.p < 2 || presentation.q < 2)
    cursor.fail("the type {" + std::to_string(presentation.p) + "," +
                std::to_string(presentation.q) + "} needs p >= 2 and q >= 2");
  if (cursor.accept('_'))
    presentation.stated_petrie = static_cast<int>(cursor.number(kMaxExponent, "the Petrie length"));
}

// The rest of the header line: "Order N", "mV = a", "mF = b", each optional, in this order.
void parse_header_figures(Cursor& cursor, Presentation& presentation) {
  cursor.skip_blanks();
  if (cursor.accept_word("Order")) {
    cursor.skip_blanks();
    presentation.stated_order =
        static_cast<std::size_t>(cursor.number(1'000'000'000'000LL, "the order"));
    cursor.skip_blanks();
  }
  for (const char* key : {"mV", "mF"}) {
    if (!cursor.accept_word(key)) continue;
    cursor.skip_blanks();
    cursor.expect('=', std::string("after ") + key);
    cursor.skip_blanks();
    cursor.number(kMaxExponent, key);
    cursor.skip_blanks();
  }
  if (!cursor.at_end() && !cursor.peek_is('\n'))
    cursor.fail("unexpected " + cursor.found() +
                " in the header line; expected 'Order N', 'mV = a' or 'mF = b'");
}

}  // namespace

std::vector<Word> parse_relator_list(std::string_view text, const TextOrigin& origin) {
  Cursor cursor(text, origin);
  std::vector<Word> relators = parse_relators_at(cursor);
  expect_only_whitespace(cursor, "the relator list");
  return relators;
}

Presentation parse_conder_entry(std::string_view text, const std::string& source) {
  Cursor cursor(text, TextOrigin{source, 1, 1});
  cursor.skip_whitespace();
  if (cursor.at_end())
    cursor.fail(
        "the presentation is empty; expected an entry like 'R3.1 : Type {3,7}_8 ...' "
        "followed by its relators '[ ... ]'");
  Presentation presentation;
  presentation.name = parse_name(cursor);
  parse_type(cursor, presentation);
  parse_header_figures(cursor, presentation);
  while (!cursor.at_end() && !cursor.peek_is('[')) cursor.advance();
  presentation.relators = parse_relators_at(cursor);
  expect_only_whitespace(cursor, "the relator list (a presentation file holds one entry)");
  if (presentation.name.empty()) presentation.name = source;
  return presentation;
}

}  // namespace tessera::regmap
