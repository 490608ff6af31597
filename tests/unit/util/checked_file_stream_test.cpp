// CheckedFileStream (framework/util/checked_file_stream.h) in direct mode writes the file
// that buffered mode and a plain model of the writes (a string written at positions) give:
// appends across its 4 MB chunks (also written in place: room and commit), seeks back into chunks already on their way to the disk
// and into the chunk being filled, a seek past the end (zeros in the gap), single bytes.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <unistd.h>

#include "framework/util/checked_file_stream.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The same writes into a stream and into a string: the string is the file they make.
struct Both {
  CheckedFileStream& stream;
  std::string model;
  std::size_t at = 0;

  void write(const std::string& bytes) {
    stream.write(bytes.data(), std::streamsize(bytes.size()));
    if (model.size() < at + bytes.size()) model.resize(at + bytes.size(), '\0');
    model.replace(at, bytes.size(), bytes);
    at += bytes.size();
  }
  void put(char c) {
    stream.put(c);
    write_model(std::string(1, c));
  }
  // Through the buffer's room() and commit(), as the .vtp writer encodes into it; a byte
  // through sputn where there is no room (a put position before the chunk being filled).
  void write_in_place(const std::string& bytes) {
    auto& file = dynamic_cast<CheckedFileBuffer&>(*stream.rdbuf());
    for (std::size_t done = 0; done < bytes.size();) {
      const std::span<char> room = file.room();
      if (room.empty()) {
        file.sputn(bytes.data() + done, 1);
        ++done;
        continue;
      }
      const std::size_t n = std::min(room.size(), bytes.size() - done);
      std::copy_n(bytes.data() + done, n, room.data());
      file.commit(n);
      done += n;
    }
    write_model(bytes);
  }
  void write_model(const std::string& bytes) {
    if (model.size() < at + bytes.size()) model.resize(at + bytes.size(), '\0');
    model.replace(at, bytes.size(), bytes);
    at += bytes.size();
  }
  void seek(std::size_t to) {
    stream.seekp(std::streamoff(to));
    at = to;
  }
};

std::string bytes_of(std::mt19937& random, std::size_t size) {
  std::string s(size, '\0');
  for (char& c : s) c = char(random() & 0xFF);
  return s;
}

// Writes a sequence made from `seed` in `mode`; returns the model's text after checking the file.
std::string write_sequence(const fs::path& file, FileWrite mode, unsigned seed) {
  std::mt19937 random(seed);
  CheckedFileStream stream(file, file, mode);
  Both both{stream, {}};
  constexpr std::size_t MB = 1 << 20;
  both.write(bytes_of(random, 3 * MB + 17));       // inside the first chunk
  const std::size_t header = both.at;
  both.write(std::string(40, 'h'));                // a placeholder, as VTK's compression header
  both.write(bytes_of(random, 9 * MB + 5));        // across two chunk ends
  both.write_in_place(bytes_of(random, 5 * MB + 7));  // in place, across a chunk end
  const std::size_t end = both.at;
  both.seek(header);                               // back into a chunk written (or on its way)
  both.write_in_place(bytes_of(random, 20));       // no room there in direct mode
  both.write(bytes_of(random, 20));
  both.seek(end - 100);                            // back into the chunk being filled
  both.write(bytes_of(random, 50));
  both.seek(4 * MB - 10);                          // a patch that runs on into later bytes
  both.write(bytes_of(random, 30));
  both.seek(end);
  for (int i = 0; i < 1000; ++i) both.put(char('a' + i % 26));
  CHECK(std::size_t(stream.tellp()) == both.at);
  both.seek(both.model.size() + 5 * MB + 3);       // past the end: zeros in between
  both.write(bytes_of(random, 2 * MB));
  stream.close();
  CHECK(file_text(file) == both.model);
  return both.model;
}

}  // namespace

TEST_CASE("CheckedFileStream: direct mode writes the file buffered mode and the model give") {
  const fs::path dir = fs::temp_directory_path() / ("subdiv_checked_stream_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (unsigned seed : {1u, 2u}) {
    CAPTURE(seed);
    const std::string direct = write_sequence(dir / "direct.bin", FileWrite::Direct, seed);
    const std::string buffered = write_sequence(dir / "buffered.bin", FileWrite::Buffered, seed);
    CHECK(direct == buffered);
    CHECK(file_text(dir / "direct.bin") == file_text(dir / "buffered.bin"));
  }
  fs::remove_all(dir);
}

TEST_CASE("CheckedFileStream: a small file in direct mode (no whole chunk) is written at close") {
  const fs::path dir = fs::temp_directory_path() / ("subdiv_checked_stream_small_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  CheckedFileStream stream(dir / "small.txt", dir / "small.txt", FileWrite::Direct);
  stream << "<VTKFile>";
  stream.seekp(1);
  stream << "v";
  stream.seekp(0, std::ios::end);
  stream << "</VTKFile>\n";
  stream.close();
  CHECK(file_text(dir / "small.txt") == "<vTKFile></VTKFile>\n");
  fs::remove_all(dir);
}
