// VTK's XML reader sizes a cell section's connectivity by the last value of its offsets
// and allocates that many ids before it reads them (2^50 bytes for a last offset of 2^47:
// found by fuzz_read_vtp). The check reads that value in every form VTK reads: here files
// are written by hand in each form with a last offset that is right (read), one too many
// (refused, naming the value, which shows it was decoded exactly) and 2^47 (refused).
#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <vtkNew.h>
#include <vtkZLibDataCompressor.h>

#include "framework/io/mesh_read.h"
#include "framework/io/vtk/base64_encode.h"
#include "framework/io/vtk/vtk_read.h"
#include "io_test_support.h"

namespace subdiv::test {
namespace {

struct Form {
  const char* name;
  bool appended, base64, compressed, big_endian;
};

constexpr Form kForms[] = {
    {"ascii", false, false, false, false},
    {"inline binary", false, true, false, false},
    {"inline binary, zlib", false, true, true, false},
    {"appended raw", true, false, false, false},
    {"appended raw, zlib", true, false, true, false},
    {"appended base64, zlib", true, true, true, false},
    {"appended raw, big-endian", true, false, false, true},
    {"appended raw, zlib, big-endian", true, false, true, true},
};

// Blocks of 16 bytes: an array of five Int64 values spans three, the last value in the third.
constexpr std::uint64_t kBlock = 16;

std::string base64(const std::string& bytes) {
  std::string out(4 * (bytes.size() / 3) + 4, '\0');
  const auto* in = reinterpret_cast<const unsigned char*>(bytes.data());
  io_detail::encode_base64_triplets(in, bytes.size() / 3, out.data());
  const std::size_t tail = io_detail::encode_base64_tail(in + 3 * (bytes.size() / 3), bytes.size() % 3,
                                                         out.data() + 4 * (bytes.size() / 3));
  out.resize(4 * (bytes.size() / 3) + tail);
  return out;
}

std::string words(const std::vector<std::uint64_t>& values, bool big_endian) {
  std::string out;
  for (const std::uint64_t v : values)
    for (int i = 0; i < 8; ++i) out.push_back(char((v >> (8 * (big_endian ? 7 - i : i))) & 0xFF));
  return out;
}

// One Int64 array's data as VTK writes it in `form`: its header and values (a base64 run
// each when compressed, one run otherwise).
std::string binary_data(const Form& form, const std::vector<std::uint64_t>& values) {
  const std::string plain = words(values, form.big_endian);
  if (!form.compressed) {
    const std::string data = words({plain.size()}, form.big_endian) + plain;
    return form.base64 ? base64(data) : data;
  }
  vtkNew<vtkZLibDataCompressor> zlib;
  std::vector<std::uint64_t> header = {(plain.size() + kBlock - 1) / kBlock, kBlock, plain.size() % kBlock};
  std::string blocks;
  for (std::size_t at = 0; at < plain.size(); at += kBlock) {
    const std::size_t n = std::min<std::size_t>(kBlock, plain.size() - at);
    std::vector<unsigned char> packed(zlib->GetMaximumCompressionSpace(n));
    const std::size_t size =
        zlib->Compress(reinterpret_cast<const unsigned char*>(plain.data() + at), n, packed.data(), packed.size());
    REQUIRE(size > 0);
    header.push_back(size);
    blocks.append(reinterpret_cast<const char*>(packed.data()), size);
  }
  const std::string head = words(header, form.big_endian);
  return form.base64 ? base64(head) + base64(blocks) : head + blocks;
}

// Three points and `faces` copies of one triangle whose offsets end in `last`; every array
// (field data too) in `form`, integers as Int64, coordinates as Float64.
std::string triangle_file(const Form& form, int faces, std::uint64_t last) {
  std::vector<std::uint64_t> connectivity, offsets;
  for (int f = 0; f < faces; ++f) {
    connectivity.insert(connectivity.end(), {0, 1, 2});
    offsets.push_back(3 * std::uint64_t(f + 1));
  }
  offsets.back() = last;
  const std::vector<double> corners = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<std::uint64_t> coordinates;
  for (const double x : corners) coordinates.push_back(std::bit_cast<std::uint64_t>(x));
  std::string appended;
  const auto array = [&](const std::string& attributes, const std::vector<std::uint64_t>& values, bool real) {
    const std::string tag = "<DataArray " + attributes;
    if (form.appended) {
      const std::string offset = std::to_string(appended.size());
      appended += binary_data(form, values);
      return tag + " format=\"appended\" offset=\"" + offset + "\"/>\n";
    }
    if (form.base64) return tag + " format=\"binary\">" + binary_data(form, values) + "</DataArray>\n";
    std::string text;
    for (const std::uint64_t v : values) text += (real ? fmt::format("{}", std::bit_cast<double>(v)) : std::to_string(v)) + " ";
    return tag + " format=\"ascii\">" + text + "</DataArray>\n";
  };
  const std::string field = array("type=\"Int64\" Name=\"label\" NumberOfTuples=\"2\"", {7, 8}, false);
  const std::string points = array("type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", coordinates, true);
  std::string cells = array("type=\"Int64\" Name=\"connectivity\"", connectivity, false);
  cells += array("type=\"Int64\" Name=\"offsets\"", offsets, false);
  std::string file = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"") +
                     (form.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"UInt64\"" +
                     (form.compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<PolyData>\n" +
                     "<FieldData>\n" + field + "</FieldData>\n" +
                     "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"" + std::to_string(faces) + "\">\n" +
                     "<Points>\n" + points + "</Points>\n<Polys>\n" + cells + "</Polys>\n</Piece>\n</PolyData>\n";
  if (form.appended) file += "<AppendedData encoding=\"" + std::string(form.base64 ? "base64" : "raw") + "\">\n_" + appended + "\n</AppendedData>\n";
  return file + "</VTKFile>\n";
}

TEST_CASE(".vtp: the last cell offset is read as VTK reads it and may not exceed the connectivity") {
  TempDir dir;
  for (const Form& form : kForms)
    for (const int faces : {1, 5}) {
      CAPTURE(form.name);
      CAPTURE(faces);
      const fs::path file = dir / "cells.vtp";
      write_text(file, triangle_file(form, faces, 3 * std::uint64_t(faces)));
      CHECK(io_detail::read_vtk_polydata_with_vtk(file).face_count() == std::size_t(faces));

      for (const std::uint64_t last : {3 * std::uint64_t(faces) + 1, std::uint64_t(1) << 47}) {
        write_text(file, triangle_file(form, faces, last));
        const std::string m = error_of([&] { read_mesh(file); });
        CHECK_MESSAGE(contains(m, file.string() + ":"), m);
        CHECK_MESSAGE(contains(m, "the last offset of <Polys> is " + std::to_string(last) +
                                      ", but its connectivity array holds at most " + std::to_string(3 * faces) +
                                      " values"),
                      m);
      }
    }
}

TEST_CASE(".vtp ascii offsets: read up to where VTK's stream stops, as VTK does") {
  TempDir dir;
  const fs::path file = dir / "cells.vtp";
  std::string text = triangle_file(kForms[0], 1, 3);
  // VTK's stream reads "3" and stops at 'x': the last offset is 3, and the file reads.
  text.replace(text.find("\">3 </DataArray>\n</Polys>"), 16, "\">3x99999999999 </DataArray>");
  write_text(file, text);
  CHECK(io_detail::read_vtk_polydata_with_vtk(file).face_count() == 1);
  // A sign is part of the number: "+140737488355328" is the offset 2^47.
  text.replace(text.find("3x99999999999"), 13, "+140737488355328");
  write_text(file, text);
  CHECK(contains(error_of([&] { read_mesh(file); }), "the last offset of <Polys> is 140737488355328"));
}

}  // namespace
}  // namespace subdiv::test

namespace subdiv::test {
namespace {

TEST_CASE(".vtp: arrays VTK sizes from a count must hold that many values, in every form") {
  TempDir dir;
  const fs::path file = dir / "sizes.vtp";
  for (const Form& form : kForms) {
    CAPTURE(form.name);
    const std::string good = triangle_file(form, 1, 3);
    // 4 x 10^8 points: within memory for the sizes check (19 GB), and VTK allocated 9.6 GB
    // for the coordinates before it found them missing.
    for (const char* points : {"4", "400000000"}) {
      std::string text = good;
      text.replace(text.find("NumberOfPoints=\"3\""), 18, std::string("NumberOfPoints=\"") + points + "\"");
      write_text(file, text);
      const std::string m = error_of([&] { read_mesh(file); });
      CHECK_MESSAGE(contains(m, "array 'Points' needs " + std::to_string(3 * std::stoll(points)) +
                                    " values (NumberOfPoints = " + points + " x 3 components), but its data holds at most 9"),
                    m);
    }
    std::string tuples = good;
    tuples.replace(tuples.find("NumberOfTuples=\"2\""), 18, "NumberOfTuples=\"300000000\"");
    write_text(file, tuples);
    const std::string m = error_of([&] { read_mesh(file); });
    CHECK_MESSAGE(contains(m, "array 'label' needs 300000000 values (NumberOfTuples = 300000000 x 1 components), but "
                              "its data holds at most 2"),
                  m);
  }
}

}  // namespace
}  // namespace subdiv::test
