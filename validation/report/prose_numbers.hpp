#pragma once
// Each number once per sentence: a sentence of the report's prose that states one quantity twice in
// two roundings ("effective sample size 1340; ... rests on 1300 effective points") gives the reader
// two values of it. report warns of each such sentence it writes; tests plant them.
#include <string>
#include <vector>

namespace validation {

struct RestatedNumber {
  std::string sentence;         // as the prose has it (table lines, code spans and link targets left out)
  std::string longer, shorter;  // the two numbers as written: `shorter` is `longer` rounded to fewer significant digits
};

// The sentences of `markdown` (split at ". ", "? ", "! " and blank lines) where a number is another
// rounded to fewer significant digits, both of two significant digits or more and each standing
// alone: a number in a list, a range or a "±" (the paper's 0.73, 0.67 and 0.57 beside our
// 0.7328 ± 0.0020; a sample range 1.07–1.08 beside a mean 1.0770) compares values and is not counted.
// Table lines (starting with '|'), `code spans` and the targets of links are not prose.
std::vector<RestatedNumber> numbers_restated(const std::string& markdown);

}  // namespace validation
