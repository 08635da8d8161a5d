#pragma once
// A set of values of a small enum (at most 64 values, ending in `Count`), as a bit mask. Used
// where a declaration lists enum values (a pass's inputs and resources), so that a set is a
// value that can sit in a constant table and a typo is a compile error.
#include <cstdint>
#include <initializer_list>

namespace vct {

template <class Enum>
class EnumSet {
    static_assert(std::size_t(Enum::Count) <= 64, "EnumSet holds at most 64 values");

public:
    constexpr EnumSet() = default;
    constexpr EnumSet(std::initializer_list<Enum> values) {
        for (Enum v : values) bits_ |= bit(v);
    }
    constexpr bool contains(Enum v) const { return (bits_ & bit(v)) != 0; }
    constexpr bool intersects(EnumSet other) const { return (bits_ & other.bits_) != 0; }
    constexpr bool empty() const { return bits_ == 0; }
    constexpr EnumSet& operator|=(EnumSet other) {
        bits_ |= other.bits_;
        return *this;
    }
    constexpr bool operator==(const EnumSet&) const = default;

    // Calls f(value) for every value in the set, in enum order.
    template <class F>
    constexpr void forEach(F&& f) const {
        for (std::size_t i = 0; i < std::size_t(Enum::Count); ++i)
            if (bits_ & (std::uint64_t(1) << i)) f(Enum(i));
    }

private:
    static constexpr std::uint64_t bit(Enum v) { return std::uint64_t(1) << std::size_t(v); }
    std::uint64_t bits_ = 0;
};

}  // namespace vct
