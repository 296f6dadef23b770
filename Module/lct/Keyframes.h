/**
 * @file Keyframes.h
 * @brief Keys ordered by strictly increasing time: O(log n) edits, and a flat view (times kept
 *        contiguous for the curve weights of lct/Curves.h) rebuilt in O(n) when asked for. The
 *        bookkeeping shared by the interpolators.
 *
 * `Key` is any type with a `double Time` member. A key set at an existing time replaces that
 * key, as VTK's interpolators do. Loading n keys in any order therefore costs O(n log n) (a
 * sorted vector would move O(n) keys per insertion in reverse time order: 20 000 prop keys took
 * 90 s that way), and the flat view is rebuilt once, by the first evaluation after the edits.
 */
#ifndef lct_Keyframes_h
#define lct_Keyframes_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <vector>

namespace lct
{

template <typename Key>
class Keyframes
{
public:
  std::size_t size() const { return this->Keys.size(); }
  bool empty() const { return this->Keys.empty(); }
  double minimumTime() const { return this->empty() ? 0.0 : this->Keys.begin()->first; }
  double maximumTime() const { return this->empty() ? 0.0 : this->Keys.rbegin()->first; }

  /// The key at exactly time t, or null. (NaN compares unordered with every time, so std::map
  /// would take it as equivalent to a key: it has none.)
  const Key* find(double t) const
  {
    const auto it = std::isnan(t) ? this->Keys.end() : this->Keys.find(t);
    return it == this->Keys.end() ? nullptr : &it->second;
  }
  Key* find(double t)
  {
    const auto it = std::isnan(t) ? this->Keys.end() : this->Keys.find(t);
    return it == this->Keys.end() ? nullptr : &it->second;
  }
  /// The nearest key strictly before / after time t, or null.
  const Key* before(double t) const
  {
    auto it = this->Keys.lower_bound(t);
    return it == this->Keys.begin() ? nullptr : &std::prev(it)->second;
  }
  const Key* after(double t) const
  {
    const auto it = this->Keys.upper_bound(t);
    return it == this->Keys.end() ? nullptr : &it->second;
  }
  /// The keys around time t: up to `count` strictly before t and up to `count`
  /// strictly after it, each in time order (O(log n + count), no flat view needed).
  /// Fewer than `count` on a side means that side reaches the first or the last key.
  void around(
    double t, int count, std::vector<const Key*>& before, std::vector<const Key*>& after) const
  {
    before.clear();
    after.clear();
    for (auto it = this->Keys.lower_bound(t);
         it != this->Keys.begin() && static_cast<int>(before.size()) < count;)
    {
      --it;
      before.push_back(&it->second);
    }
    std::reverse(before.begin(), before.end());
    for (auto it = this->Keys.upper_bound(t);
         it != this->Keys.end() && static_cast<int>(after.size()) < count; ++it)
    {
      after.push_back(&it->second);
    }
  }
  /// Whether a key at t keeps the span of the key times finite (the curve weights divide by
  /// time differences).
  bool keepsFiniteSpan(double t) const
  {
    return this->empty() ||
      std::isfinite(std::max(t, this->maximumTime()) - std::min(t, this->minimumTime()));
  }
  /// Whether t is later than every key (an append keeps a flat view cheap to extend).
  bool isAppend(double t) const { return this->empty() || t > this->maximumTime(); }

  /// Inserts `key`, or replaces the key at its time. A replacement or an append keeps the flat
  /// view current.
  void set(const Key& key)
  {
    const bool append = this->isAppend(key.Time);
    const auto [it, inserted] = this->Keys.insert_or_assign(key.Time, key);
    if (!inserted)
    {
      return; // the same node: the flat view still points at it
    }
    if (append && this->Flat)
    {
      this->Times.push_back(key.Time);
      this->Pointers.push_back(&it->second);
    }
    else
    {
      this->Flat = false;
    }
  }
  /// The position of the key at time t in the flat view, or -1. Requires flat().
  int index(double t) const
  {
    const auto it = std::lower_bound(this->Times.begin(), this->Times.end(), t);
    return (it != this->Times.end() && *it == t) ? static_cast<int>(it - this->Times.begin()) : -1;
  }
  /// Removes the key at time t; false when there is none.
  bool erase(double t)
  {
    if (std::isnan(t) || this->Keys.erase(t) == 0)
    {
      return false;
    }
    this->Flat = false;
    return true;
  }
  void clear()
  {
    this->Keys.clear();
    this->Times.clear();
    this->Pointers.clear();
    this->Flat = true;
  }

  /// The flat view: valid while `flat()`, i.e. until an edit other than an append.
  bool flat() const { return this->Flat; }
  void flatten()
  {
    if (this->Flat)
    {
      return;
    }
    this->Times.clear();
    this->Pointers.clear();
    this->Times.reserve(this->Keys.size());
    this->Pointers.reserve(this->Keys.size());
    for (const auto& [time, key] : this->Keys)
    {
      this->Times.push_back(time);
      this->Pointers.push_back(&key);
    }
    this->Flat = true;
  }
  /// The key times in order (what lct::curveWeights takes). Requires flat().
  const std::vector<double>& times() const { return this->Times; }
  /// The i-th key in time order. Requires flat().
  const Key& operator[](std::size_t i) const { return *this->Pointers[i]; }

  /// Every key in time order (no flat view needed).
  template <typename Visit>
  void forEach(Visit&& visit) const
  {
    for (const auto& entry : this->Keys)
    {
      visit(entry.second);
    }
  }

private:
  std::map<double, Key> Keys;
  std::vector<double> Times;
  std::vector<const Key*> Pointers;
  bool Flat = true;
};

} // namespace lct

#endif
