// An id-keyed list of owned items, the shape of the technique and measure registries
// (techniques/registry.h, harness/measures/measure.h): T has info().id, a std::string.
#pragma once

#include <algorithm>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

namespace tb::mesh {

template <typename T>
class Registry {
 public:
  // Ignores a second item with an id already present and returns false.
  bool add(std::unique_ptr<T> item) {
    if (find(item->info().id) != nullptr) return false;
    items_.push_back(std::move(item));
    return true;
  }
  const T* find(std::string_view id) const {
    for (const auto& item : items_) {
      if (item->info().id == id) return item.get();
    }
    return nullptr;
  }
  // Sorted by id, so every listing and every run has the same order.
  std::vector<const T*> all() const {
    std::vector<const T*> result;
    for (const auto& item : items_) result.push_back(item.get());
    std::sort(result.begin(), result.end(),
              [](const T* a, const T* b) { return a->info().id < b->info().id; });
    return result;
  }

 private:
  std::vector<std::unique_ptr<T>> items_;
};

}  // namespace tb::mesh
