#pragma once
// One name table per enum of a setting: the names scene files, reports and messages use for its values. The scene
// reader looks a name up, the report writes the value's name, a message lists the names; tests check that the
// docs list them (tests/coupling/test_scene_loader.cpp).
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sphslope {

template <class E>
struct Named {
  std::string_view name;
  E value;
};

template <class E, std::size_t N>
using NameTable = std::array<Named<E>, N>;

// The value's name; empty if the table lacks it (every table lists every enumerator: tests check the round trip).
template <class E, std::size_t N>
constexpr std::string_view name_of(const NameTable<E, N>& table, E value) {
  for (const Named<E>& entry : table)
    if (entry.value == value) return entry.name;
  return {};
}

// The value with this name, if any.
template <class E, std::size_t N>
constexpr std::optional<E> value_named(const NameTable<E, N>& table, std::string_view name) {
  for (const Named<E>& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

// The names for a message: "a, b, c" (quoted = false) or "\"a\", \"b\" or \"c\"" (quoted = true).
template <class E, std::size_t N>
std::string names_listed(const NameTable<E, N>& table, bool quoted = false) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += quoted ? (i + 1 == N ? " or " : ", ") : ", ";
    // appended piece by piece: g++ 12 warns falsely (-Wrestrict) on "\"" + std::string(...) inlined here
    if (quoted) out += '"';
    out.append(table[i].name);
    if (quoted) out += '"';
  }
  return out;
}

// The value named `key`; otherwise std::invalid_argument "<what> '<key>': expected "a" or "b"".
template <class E, std::size_t N>
E value_named_or_throw(const NameTable<E, N>& table, const std::string& key, const std::string& what) {
  if (const auto value = value_named(table, key)) return *value;
  throw std::invalid_argument(what + " '" + key + "': expected " + names_listed(table, true));
}

}  // namespace sphslope
