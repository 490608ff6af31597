#pragma once
// Reads the binary data of one array of a .vtp file byte by byte, as vtkXMLDataParser
// reads it: raw bytes, or base64 text decoded on the way (characters outside base64 are
// skipped, '<' ends inline text). For the checks that run before VTK's reader allocates
// (vtk_xml_blocks.h, vtk_cell_offsets_check.h), not for bulk decoding (vtp_array_decode.h).
// Internal to io/.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace subdiv::io_detail {

class XmlDataReader {
public:
  XmlDataReader(std::string_view bytes, std::size_t at, bool base64) : bytes_(bytes), pos_(at), base64_(base64) {}

  // The next `n` bytes of data, or nullopt if the data ends first.
  std::optional<std::string> take(std::size_t n) {
    std::string out;
    while (out.size() < n) {
      if (!base64_) {
        if (pos_ >= bytes_.size()) return std::nullopt;
        out.push_back(bytes_[pos_++]);
        continue;
      }
      if (pending_ == pending_end_ && !decode_group()) return std::nullopt;
      out.push_back(char(pending_bytes_[pending_++]));
    }
    return out;
  }

  // Passes over `n` bytes; false if the data ends first.
  bool skip(std::uint64_t n) {
    if (!base64_) {
      if (n > bytes_.size() - std::min(pos_, bytes_.size())) return false;
      pos_ += std::size_t(n);
      return true;
    }
    for (; n > 0; --n) {
      if (pending_ == pending_end_ && !decode_group()) return false;
      ++pending_;
    }
    return true;
  }

  // Base64 data written in several runs (the header of compressed data, then the blocks):
  // the rest of the current group is the first run's '=' padding, not data.
  void end_run() { pending_ = pending_end_; }

  // Data bytes left in the file from here (base64: what the text decodes to, at most).
  double remaining() const {
    const double left = double(bytes_.size() - std::min(pos_, bytes_.size()));
    return base64_ ? left * 3 / 4 + double(pending_end_ - pending_) : left;
  }

private:
  static int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  }

  bool decode_group() {
    int values[4], n = 0;
    while (n < 4 && pos_ < bytes_.size()) {
      const char c = bytes_[pos_++];
      if (c == '=') values[n++] = 0;
      else if (const int v = base64_value(c); v >= 0) values[n++] = v;
      else if (c == '<') return false;  // the element ended
    }
    if (n < 4) return false;
    const std::uint32_t bits = (values[0] << 18) | (values[1] << 12) | (values[2] << 6) | values[3];
    for (int i = 0; i < 3; ++i) pending_bytes_[i] = (bits >> (8 * (2 - i))) & 0xFF;
    pending_ = 0, pending_end_ = 3;
    return true;
  }

  std::string_view bytes_;
  std::size_t pos_;
  bool base64_;
  unsigned char pending_bytes_[3] = {};
  int pending_ = 0, pending_end_ = 0;
};

}  // namespace subdiv::io_detail
