#include "TextFormats.h"

#include <cstdio>

TextLines::TextLines(std::istream& stream)
  : Stream(stream)
{
}

bool TextLines::Next(std::string& line)
{
  line.clear();
  std::istream::int_type c = this->Stream.get();
  if (c == std::istream::traits_type::eof())
  {
    return false;
  }
  for (; c != std::istream::traits_type::eof(); c = this->Stream.get())
  {
    if (c == '\n')
    {
      break;
    }
    if (c == '\r')
    {
      if (this->Stream.peek() == '\n')
      {
        this->Stream.get();
      }
      break;
    }
    line += static_cast<char>(c);
  }
  if (++this->LineNumber == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
  {
    line.erase(0, 3);
  }
  return true;
}

std::string CsvField(const std::string& text)
{
  if (text.find_first_of(",\"\r\n") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c;
    if (c == '"')
    {
      quoted += '"';
    }
  }
  return quoted + "\"";
}

namespace
{
// The length of the valid UTF-8 sequence starting at text[at], 0 if there is none there
// (a stray continuation byte, a sequence cut short, an overlong form, a surrogate).
std::size_t Utf8SequenceLength(const std::string& text, std::size_t at)
{
  const auto byte = [&text](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(at);
  const std::size_t length = lead < 0x80 ? 1 : lead >= 0xC2 && lead <= 0xDF ? 2
    : lead >= 0xE0 && lead <= 0xEF                                          ? 3
    : lead >= 0xF0 && lead <= 0xF4                                          ? 4
                                                                            : 0;
  if (length == 0 || at + length > text.size())
  {
    return 0;
  }
  for (std::size_t k = 1; k < length; ++k)
  {
    if ((byte(at + k) & 0xC0) != 0x80)
    {
      return 0;
    }
  }
  const unsigned char second = length > 1 ? byte(at + 1) : 0;
  if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second >= 0xA0) ||
    (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second >= 0x90))
  {
    return 0;
  }
  return length;
}
}

std::string JsonString(const std::string& text)
{
  std::string out = "\"";
  for (std::size_t at = 0; at < text.size();)
  {
    const char c = text[at];
    const std::size_t length = Utf8SequenceLength(text, at);
    if (length == 0)
    {
      out += "\\ufffd";
      ++at;
      continue;
    }
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
      out += escaped;
    }
    else
    {
      out.append(text, at, length);
    }
    at += length;
  }
  return out + "\"";
}

std::string Excerpt(const std::string& text, std::size_t limit)
{
  std::string out = text.size() > limit ? text.substr(0, limit) + "..." : text;
  for (char& c : out)
  {
    c = static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  }
  return out;
}
