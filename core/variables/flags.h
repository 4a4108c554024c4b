// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mc {

/// A named boolean property (ACTIVE, SLAVE, ...). Each flag owns one bit; construction
/// registers it by name so that settings and outputs can refer to it.
class Flag {
 public:
  explicit Flag(std::string name);
  Flag(const Flag&) = delete;
  Flag& operator=(const Flag&) = delete;

  const std::string& Name() const noexcept { return name_; }
  std::uint64_t Bit() const noexcept { return bit_; }

  static const Flag& Get(const std::string& name);  ///< throws InputError with suggestions
  static std::vector<const Flag*> All();

 private:
  std::string name_;
  std::uint64_t bit_;
};

/// The set of flags of a node, element, condition or model part. A flag is either set, reset
/// (explicitly false) or undefined.
class Flags {
 public:
  bool Is(const Flag& f) const noexcept { return (values_ & f.Bit()) != 0; }
  bool IsNot(const Flag& f) const noexcept { return !Is(f); }
  bool IsDefined(const Flag& f) const noexcept { return (defined_ & f.Bit()) != 0; }
  void Set(const Flag& f, bool value = true) noexcept {
    defined_ |= f.Bit();
    values_ = value ? (values_ | f.Bit()) : (values_ & ~f.Bit());
  }
  void Reset(const Flag& f) noexcept {
    defined_ &= ~f.Bit();
    values_ &= ~f.Bit();
  }
  void Clear() noexcept { defined_ = values_ = 0; }

 private:
  std::uint64_t values_ = 0;
  std::uint64_t defined_ = 0;
};

// Kernel flags (Kratos names). Applications may define more, up to 64 in total.
extern const Flag ACTIVE;
extern const Flag SLAVE;
extern const Flag MASTER;
extern const Flag INTERFACE;
extern const Flag ISOLATED;
extern const Flag SLIP;
extern const Flag MARKER;
extern const Flag CONTACT;
extern const Flag INTERACTION;
extern const Flag MODIFIED;
extern const Flag BLOCKED;
extern const Flag RIGID;
extern const Flag TO_SPLIT;
extern const Flag TO_ERASE;
extern const Flag VISITED;
extern const Flag SELECTED;
extern const Flag BOUNDARY;
extern const Flag STRUCTURE;

}  // namespace mc
