// Text as the programs read and write it: input lines as editors and other tools write them
// (a UTF-8 byte-order mark, CR LF or lone CR line ends, as the mesh readers take them), and
// fields of the CSV and JSON files the programs write, quoted so that any name fits.
#ifndef TextFormats_h
#define TextFormats_h

#include <istream>
#include <string>

/// The lines of a text stream: a UTF-8 byte-order mark at its start is dropped, and LF, CR LF
/// and a lone CR (old Mac tools) each end a line.
class TextLines
{
public:
  explicit TextLines(std::istream& stream);
  /// The next line, without its end; false at the end of the stream.
  bool Next(std::string& line);
  /// The number of the line Next returned last, from 1.
  long long Number() const { return this->LineNumber; }

private:
  std::istream& Stream;
  long long LineNumber = 0;
};

/// A CSV field (RFC 4180): as it is, or in double quotes (doubled inside) when it holds a
/// comma, a quote or a line break.
std::string CsvField(const std::string& text);

/// A JSON string, quoted and escaped. A file name is bytes, not necessarily UTF-8: a byte
/// that is not part of valid UTF-8 becomes U+FFFD, so that the JSON stays valid.
std::string JsonString(const std::string& text);

/// `text` cut to at most `limit` characters for a one-line message, "..." marking the cut,
/// with control characters as '?'.
std::string Excerpt(const std::string& text, std::size_t limit = 80);

#endif
