#pragma once

namespace apcs {

// The lambdas of a std::visit as one overload set (lager's and the C++ reference's idiom): a
// variant's alternative that no lambda takes does not compile.
template <typename... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
// C++20 deduces an aggregate's arguments without it; Clang before 17 does not.
template <typename... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

} // namespace apcs
