/**
 * @file Keyframes.h
 * @brief Keys ordered by strictly increasing time, with their times kept contiguous for the curve
 *        weights (lct/Curves.h). The bookkeeping shared by the interpolators.
 *
 * `Key` is any type with a `double Time` member. A key added at an existing time replaces that
 * key, as VTK's interpolators do.
 */
#ifndef lct_Keyframes_h
#define lct_Keyframes_h

#include <algorithm>
#include <cstddef>
#include <vector>

namespace lct
{

template <typename Key>
class Keyframes
{
public:
  std::size_t size() const { return this->Keys.size(); }
  bool empty() const { return this->Keys.empty(); }
  const Key& operator[](std::size_t i) const { return this->Keys[i]; }
  Key& operator[](std::size_t i) { return this->Keys[i]; }
  /// The key times, in order (what lct::curveWeights takes).
  const std::vector<double>& times() const { return this->Times; }
  double minimumTime() const { return this->empty() ? 0.0 : this->Times.front(); }
  double maximumTime() const { return this->empty() ? 0.0 : this->Times.back(); }

  /// The index of the key at time t, or -1.
  int find(double t) const
  {
    const int i = this->position(t);
    return (i < static_cast<int>(this->size()) && this->Times[i] == t) ? i : -1;
  }

  /// The index at which a key at time t belongs (that of the key it replaces, if any).
  int position(double t) const
  {
    return static_cast<int>(
      std::lower_bound(this->Times.begin(), this->Times.end(), t) - this->Times.begin());
  }

  void insert(int index, const Key& key)
  {
    this->Keys.insert(this->Keys.begin() + index, key);
    this->Times.insert(this->Times.begin() + index, key.Time);
  }
  void replace(int index, const Key& key)
  {
    this->Keys[index] = key;
    this->Times[index] = key.Time;
  }
  void erase(int index)
  {
    this->Keys.erase(this->Keys.begin() + index);
    this->Times.erase(this->Times.begin() + index);
  }
  void clear()
  {
    this->Keys.clear();
    this->Times.clear();
  }

private:
  std::vector<Key> Keys;
  std::vector<double> Times;
};

} // namespace lct

#endif
