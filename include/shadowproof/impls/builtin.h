#pragma once
/// The built-in implementations under test (library shadowproof::impls).
#include <string_view>
#include <vector>

#include "shadowproof/verify/implementation.h"

namespace shadowproof {

/// The built-in implementations (src/impls/, library shadowproof_impls): seed formulas written
/// as shaders and engines write them, and engine code from Debian packages. Sorted by name.
const std::vector<implementation>& builtin_implementations();

/// The built-in implementation called `name`; throws error "verify.unknown_impl" naming it.
const implementation& find_builtin_implementation(std::string_view name);

}  // namespace shadowproof
