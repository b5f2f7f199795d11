#pragma once

#include <cstddef>
#include <type_traits>
#include <variant>

namespace apcs {

// The index of `Wanted` among `Variant`'s alternatives, at compile time: a type not among them
// does not compile.
template <typename Variant, typename Wanted, std::size_t Index = 0>
consteval std::size_t variant_index()
{
    static_assert(Index < std::variant_size_v<Variant>, "not an alternative of the variant");
    if constexpr (std::is_same_v<std::variant_alternative_t<Index, Variant>, Wanted>)
        return Index;
    else
        return variant_index<Variant, Wanted, Index + 1>();
}

} // namespace apcs
