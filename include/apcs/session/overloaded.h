#pragma once

namespace apcs {

// The lambdas of a std::visit as one overload set (lager's and the C++ reference's idiom): a
// variant's alternative that no lambda takes does not compile.
template <typename... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};

} // namespace apcs
