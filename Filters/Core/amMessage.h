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

private:
  std::ostringstream Text;
};

#endif
