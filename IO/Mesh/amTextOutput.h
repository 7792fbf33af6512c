/**
 * @class   amTextOutput
 * @brief   Numbers and text appended to a buffer and written to a stream in large blocks: the
 *          text mesh writers' output (Medit, Gmsh), millions of numbers.
 *
 * Doubles are written in their shortest form that reads back to the same value (std::to_chars),
 * integers in decimal: several times faster than an ostream with 17 digits, and the same values
 * for every reader (meshio, Gmsh, Medit's own parsers). Ok() turns false once a write fails (a
 * full disk): the caller checks it after Flush().
 */
#ifndef amTextOutput_h
#define amTextOutput_h

#include <charconv>
#include <ostream>
#include <string>
#include <type_traits>

class amTextOutput
{
public:
  explicit amTextOutput(std::ostream& out)
    : Out(out)
  {
    this->Buffer.reserve(Block + 64);
  }
  ~amTextOutput() { this->Flush(); }
  amTextOutput(const amTextOutput&) = delete;
  amTextOutput& operator=(const amTextOutput&) = delete;

  amTextOutput& operator<<(double x)
  {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, x).ptr;
    return this->Append(text, end);
  }
  template<typename Integer, typename = std::enable_if_t<std::is_integral<Integer>::value>>
  amTextOutput& operator<<(Integer x)
  {
    char text[24];
    const auto end = std::to_chars(text, text + sizeof text, x).ptr;
    return this->Append(text, end);
  }
  amTextOutput& operator<<(const char* text) { return this->Append(text, text + std::char_traits<char>::length(text)); }
  amTextOutput& operator<<(const std::string& text) { return this->Append(text.data(), text.data() + text.size()); }

  /// Writes what is buffered; false once any write failed.
  bool Flush()
  {
    if (!this->Buffer.empty() && this->Out)
      this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
    this->Buffer.clear();
    return static_cast<bool>(this->Out.flush());
  }
  bool Ok() const { return static_cast<bool>(this->Out); }

private:
  static constexpr std::size_t Block = 1 << 20;
  amTextOutput& Append(const char* begin, const char* end)
  {
    this->Buffer.append(begin, end);
    if (this->Buffer.size() >= Block)
    {
      if (this->Out)
        this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
      this->Buffer.clear();
    }
    return *this;
  }
  std::ostream& Out;
  std::string Buffer;
};

#endif
