// An enum's names, one table per enum: nameOf prints a value, parseName reads one back and, on
// a name not in the table, throws an Error that lists them all ("unknown solver 'x' (lloyd,
// lbfgs, newton)").
#pragma once

#include "mesh.h"

#include <cstddef>
#include <string>

namespace lloydscope {

template <class E>
struct NamedValue {
  E value;
  const char* name;
};

template <class E, size_t N>
const char* nameOf(const NamedValue<E> (&names)[N], E value) {
  for (const NamedValue<E>& n : names)
    if (n.value == value) return n.name;
  return "?";
}

// `what` names the kind in the error: "solver", "stage".
template <class E, size_t N>
E parseName(const NamedValue<E> (&names)[N], const std::string& text, const char* what) {
  for (const NamedValue<E>& n : names)
    if (text == n.name) return n.value;
  std::string list;
  for (const NamedValue<E>& n : names) list += (list.empty() ? "" : ", ") + std::string(n.name);
  throw Error("unknown " + std::string(what) + " '" + text + "' (" + list + ")");
}

}  // namespace lloydscope
