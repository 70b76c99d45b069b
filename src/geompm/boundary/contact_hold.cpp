#include "geompm/boundary/contact_hold.hpp"

#include <utility>

namespace geompm {

ContactHold::ContactHold(std::vector<char> held_at_start) : start_(std::move(held_at_start)) {
  restart();
}

void ContactHold::restart() {
  held_ = start_;
  // A point held from the start counts as pressed before the first iterate, so that it never
  // "enters" contact; the others start free.
  pressed_ = start_;
  entries_.assign(start_.size(), 0);
}

void ContactHold::accept(const std::vector<char>& pressed) {
  for (std::size_t i = 0; i < held_.size(); ++i) {
    const bool now = pressed[i] != 0;
    if (now && !pressed_[i] && entries_[i] < 2) ++entries_[i];
    pressed_[i] = now;
    if (now && entries_[i] >= 2) held_[i] = 1;
  }
}

}  // namespace geompm
