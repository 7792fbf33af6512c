/**
 * @class   amMessage
 * @brief   A message built with <<, for the plain C++ cores that say why they refuse:
 *          why = amMessage() << "Region " << label << " encloses no volume.";
 */
#ifndef amMessage_h
#define amMessage_h

#include <sstream>
#include <string>

class amMessage
{
public:
  template<typename T>
  amMessage& operator<<(const T& part)
  {
    this->Text << part;
    return *this;
  }
  operator std::string() const { return this->Text.str(); }

  /// A text read from a file as it may be shown: bytes outside printable ASCII as \xNN, at most
  /// 'most' characters (then "..."), so that binary garbage quoted in a message stays one readable
  /// line of valid UTF-8.
  static std::string Printable(const std::string& text, std::size_t most = 40)
  {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < most; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      if (c >= 0x20 && c < 0x7f)
        out += static_cast<char>(c);
      else
        out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
    return text.size() > most ? out + "..." : out;
  }

private:
  std::ostringstream Text;
};

#endif
