// Numbers read from text the same way on every platform and in every locale: a whole token, in
// C's decimal form, correctly rounded. What scene parameters (`--set`, `jelly params`) and the
// data files of body modules read.
#pragma once

#include <optional>
#include <string_view>

namespace jelly {

/// The double that all of `token` spells (one leading '+' allowed), or nullopt. Takes what
/// std::from_chars takes, so `inf`, `nan` and out-of-range values pass: callers that refuse them
/// check the result.
std::optional<double> read_double(std::string_view token);

/// The integer that all of `token` spells (one leading '+' allowed), or nullopt when it is not
/// one or does not fit.
std::optional<long long> read_integer(std::string_view token);

}  // namespace jelly
