// Small helpers shared by the embind registration files (no geometry).
#pragma once

#include <emscripten/val.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hullkit_wasm {

/// A typed-array view of a result's own vector, valid until the result is deleted or the heap
/// grows: the JS layer copies it out (`.slice()`) straight away.
template <typename T>
emscripten::val view_of(const std::vector<T>& values) {
    return emscripten::val(emscripten::typed_memory_view(values.size(), values.data()));
}

/// A JS array of the strings (a report's problem lines).
inline emscripten::val string_array(const std::vector<std::string>& lines) {
    emscripten::val array = emscripten::val::array();
    for (const std::string& line : lines) array.call<void>("push", emscripten::val(line));
    return array;
}

/// A block the JS layer malloc'ed and filled, as the typed pointer the core takes.
template <typename T>
const T* heap_at(std::uintptr_t address) {
    return reinterpret_cast<const T*>(address);
}

}  // namespace hullkit_wasm
