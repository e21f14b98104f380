// Tables of things a user chooses by name (laws, kernels): each row a struct with at least `name` and
// `summary`. From the table come an option's list of names, its help text, the choices an error message
// lists, the row of a name, and (AtRow) the row's index as a compile-time constant, so that a row's values
// can be bound as template arguments once, outside the loops that use them.
#pragma once

#include <cstddef>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vofdem::table {

template <class Row, std::size_t N>
std::vector<std::string> Names(const Row (&table)[N]) {
  std::vector<std::string> names;
  for (const Row &r : table) names.emplace_back(r.name);
  return names;
}

// "a (its summary), b (its summary), ..." for an option's help.
template <class Row, std::size_t N>
std::string Help(const Row (&table)[N]) {
  std::string h;
  for (std::size_t k = 0; k < N; ++k) h += std::string(k ? ", " : "") + table[k].name + " (" + table[k].summary + ")";
  return h;
}

// "a, b or c" for an error message.
template <class Row, std::size_t N>
std::string Choices(const Row (&table)[N]) {
  std::string h;
  for (std::size_t k = 0; k < N; ++k) h += std::string(k == 0 ? "" : k + 1 == N ? " or " : ", ") + table[k].name;
  return h;
}

// The row named `name`, -1 if none.
template <class Row, std::size_t N>
int Find(const Row (&table)[N], const std::string &name) {
  for (std::size_t k = 0; k < N; ++k)
    if (name == table[k].name) return (int)k;
  return -1;
}

namespace detail {
template <class F, std::size_t... I>
auto AtRow(std::size_t row, F &&f, std::index_sequence<I...>) {
  using Result = decltype(f(std::integral_constant<std::size_t, 0>{}));
  Result result{};
  (void)((row == I ? (result = f(std::integral_constant<std::size_t, I>{}), true) : false) || ...);
  return result;
}
}  // namespace detail

// f(std::integral_constant<std::size_t, row>): the row's index as a compile-time constant, so that f can bind
// the row's values as template arguments (one instantiation per row, chosen once outside the loops).
template <std::size_t N, class F>
auto AtRow(std::size_t row, F &&f) {
  return detail::AtRow(row, std::forward<F>(f), std::make_index_sequence<N>{});
}

}  // namespace vofdem::table
