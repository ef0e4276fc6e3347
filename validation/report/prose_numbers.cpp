#include "report/prose_numbers.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace validation {

namespace {

struct Token {
  std::string text;
  std::size_t begin = 0, end = 0;
};

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '^'; }

// Whether the character that ends at s[i - 1] makes a number after it part of a name: an ASCII
// letter, digit, '_' or '^' (TC1, seed3, F^s_d), a '.' or ',' right before it (0.1.0), or a Greek
// letter (ε3, σ1: UTF-8 lead bytes 0xCE and 0xCF).
bool joins_before(const std::string& s, std::size_t i) {
  if (i == 0) return false;
  const char c = s[i - 1];
  if (is_word(c) || c == '.' || c == ',') return true;
  if ((static_cast<unsigned char>(c) & 0xC0) != 0x80 || i < 2) return false;
  const auto lead = static_cast<unsigned char>(s[i - 2]);
  return lead == 0xCE || lead == 0xCF;
}

// The prose of `markdown`: table lines dropped, `code spans` and the "(target)" of "[text](target)"
// blanked, so that their digits (paths, hashes, versions) are not read as numbers.
std::string prose_of(const std::string& markdown) {
  std::istringstream in(markdown);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("|", 0) == 0) {
      out += "\n";
      continue;
    }
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '`') {
        const std::size_t close = line.find('`', i + 1);
        if (close == std::string::npos) break;
        out += ' ', i = close;
      } else if (line[i] == ']' && i + 1 < line.size() && line[i + 1] == '(') {
        const std::size_t close = line.find(')', i + 2);
        out += ']';
        if (close == std::string::npos) break;
        i = close;
      } else {
        out += line[i];
      }
    }
    out += "\n";
  }
  return out;
}

std::vector<std::string> sentences_of(const std::string& prose) {
  std::vector<std::string> out;
  std::string current;
  for (std::size_t i = 0; i < prose.size(); ++i) {
    current += prose[i];
    const bool end_mark = (prose[i] == '.' || prose[i] == '?' || prose[i] == '!') && (i + 1 == prose.size() || std::isspace(static_cast<unsigned char>(prose[i + 1])));
    const bool blank_line = prose[i] == '\n' && i + 1 < prose.size() && prose[i + 1] == '\n';
    if (end_mark || blank_line) out.push_back(current), current.clear();
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

// The numbers of a sentence: digits with "," thousands, a decimal part and an exponent, not inside a
// word (TC1, seed3, fig07, F^s_d) and not a version's part (0.1.0).
std::vector<Token> numbers_in(const std::string& s) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < s.size();) {
    if (!is_digit(s[i]) || joins_before(s, i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < s.size() && is_digit(s[j])) ++j;
    while (j + 3 < s.size() && s[j] == ',' && is_digit(s[j + 1]) && is_digit(s[j + 2]) && is_digit(s[j + 3]) && (j + 4 == s.size() || !is_digit(s[j + 4])))
      j += 4;
    if (j + 1 < s.size() && s[j] == '.' && is_digit(s[j + 1])) {
      ++j;
      while (j < s.size() && is_digit(s[j])) ++j;
    }
    if (j + 1 < s.size() && s[j] == 'e' && (is_digit(s[j + 1]) || ((s[j + 1] == '-' || s[j + 1] == '+') && j + 2 < s.size() && is_digit(s[j + 2])))) {
      j += 2;
      while (j < s.size() && is_digit(s[j])) ++j;
    }
    const bool in_word = j < s.size() && (is_word(s[j]) || (s[j] == '.' && j + 1 < s.size() && is_digit(s[j + 1])));
    if (!in_word) out.push_back({s.substr(i, j - i), i, j});
    i = j + (in_word ? 1 : 0);
  }
  return out;
}

// Whether the text just before or after a number ties it to others: a list ("0.73, 0.67 and 0.57",
// "7.3 / 7.2"), a range ("1.07–1.08") or a "±".
bool listed(const std::string& s, const Token& t) {
  std::size_t b = t.begin;
  while (b > 0 && s[b - 1] == ' ') --b;
  const std::string before = s.substr(b >= 4 ? b - 4 : 0, b >= 4 ? 4 : b);
  const auto ends = [&](const std::string& mark) { return before.size() >= mark.size() && before.compare(before.size() - mark.size(), mark.size(), mark) == 0; };
  if (ends("–") || ends("/") || ends("±") || ends(",") || ends("and")) return true;
  std::size_t a = t.end;
  while (a < s.size() && s[a] == ' ') ++a;
  const std::string after = s.substr(a, 4);
  if (after.rfind("–", 0) == 0 || after.rfind("/", 0) == 0 || after.rfind("±", 0) == 0 || after.rfind("and ", 0) == 0) return true;
  if (after.rfind(",", 0) == 0) {
    std::size_t n = a + 1;
    while (n < s.size() && s[n] == ' ') ++n;
    return n < s.size() && (is_digit(s[n]) || s[n] == '-');
  }
  return false;
}

double value_of(const std::string& text) {
  std::string plain;
  for (char c : text)
    if (c != ',') plain += c;
  return std::strtod(plain.c_str(), nullptr);
}

// Significant digits as written: "1340" 3, "1300" 2, "0.00012" 2, "0.30" 2, "16.0" 3.
int significant_digits(const std::string& text) {
  std::string mantissa = text.substr(0, text.find('e'));
  const bool decimal = mantissa.find('.') != std::string::npos;
  std::string digits;
  for (char c : mantissa)
    if (is_digit(c)) digits += c;
  digits.erase(0, digits.find_first_not_of('0'));
  if (!decimal) digits.erase(digits.find_last_not_of('0') + 1);
  return static_cast<int>(digits.size());
}

double rounded(double x, int digits) {
  if (x == 0) return 0;
  const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(x)))));
  return std::round(x * scale) / scale;
}

}  // namespace

std::vector<RestatedNumber> numbers_restated(const std::string& markdown) {
  std::vector<RestatedNumber> out;
  for (const std::string& sentence : sentences_of(prose_of(markdown))) {
    std::vector<Token> alone;
    for (const Token& t : numbers_in(sentence))
      if (!listed(sentence, t)) alone.push_back(t);
    for (const Token& a : alone)
      for (const Token& b : alone) {
        const int ka = significant_digits(a.text), kb = significant_digits(b.text);
        if (kb < 2 || ka <= kb) continue;
        const double va = value_of(a.text), vb = value_of(b.text);
        if (va == vb || std::abs(rounded(va, kb) - vb) > 1e-9 * std::abs(vb)) continue;
        std::string shown = sentence;
        while (!shown.empty() && std::isspace(static_cast<unsigned char>(shown.front()))) shown.erase(0, 1);
        out.push_back({shown, a.text, b.text});
      }
  }
  return out;
}

}  // namespace validation
