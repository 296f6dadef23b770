/**
 * @file Format.h
 * @brief Numbers in messages: the shortest decimal that reads back as the same double, so a key
 *        time of 1e-7 is printed as 1e-07, not 0.000000, and two different times never print
 *        alike.
 */
#ifndef lct_Format_h
#define lct_Format_h

#include <charconv>
#include <string>

namespace lct
{

inline std::string formatNumber(double x)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, result.ptr);
}

} // namespace lct

#endif
