// The MCAP writer (io/mcap.hpp) against the specification's byte layout, and a property: any
// sequence of messages it writes is read back exactly, every index and CRC holding
// (tests/support/mcap_reader.hpp, a reader written from the specification).
#include "mcap_reader.hpp"

#include <antkit/io/mcap.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>

namespace mcap = antkit::io::mcap;
namespace reader = antkit::test::mcap;

namespace {

std::uint64_t u64_at(const std::string& b, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < 8; ++i)
    v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(b[at + i])) << (8 * i);
  return v;
}
std::uint32_t u32_at(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(u64_at(b + std::string(8, '\0'), at) & 0xFFFFFFFFU);
}

} // namespace

TEST_CASE("mcap crc32 is zlib's", "[io][mcap]") {
  CHECK(mcap::crc32("") == 0U);
  CHECK(mcap::crc32("123456789") == 0xCBF43926U); // the CRC-32 check value
  CHECK(mcap::crc32("The quick brown fox jumps over the lazy dog") == 0x414FA339U);
  CHECK(mcap::crc32("56789", mcap::crc32("1234")) == 0xCBF43926U); // chained
}

TEST_CASE("an empty MCAP file, byte by byte", "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out);
  w.finish();
  const std::string b = out.str();
  // magic; Header: op 1, length 14, profile "", library "antkit".
  std::string expect("\x89MCAP0\r\n", 8);
  expect += '\x01';
  expect += std::string("\x0e\0\0\0\0\0\0\0", 8);
  expect += std::string("\0\0\0\0", 4);
  expect += std::string("\x06\0\0\0antkit", 10);
  REQUIRE(b.substr(0, expect.size()) == expect);
  // DataEnd at 31: op 0x0F, length 4, the CRC of the 31 bytes before it.
  REQUIRE(b.size() > 44);
  CHECK(b[31] == '\x0f');
  CHECK(u64_at(b, 32) == 4);
  CHECK(u32_at(b, 40) == mcap::crc32(std::string_view(b).substr(0, 31)));
  // The summary at 44: one Statistics record (op 0x0B) of 46 bytes' content (8+2+4*4+8+8+4).
  CHECK(b[44] == '\x0b');
  CHECK(u64_at(b, 45) == 46);
  // Then one SummaryOffset (op 0x0E, 17 bytes) for it, the Footer and the magic.
  const std::size_t offsets = 44 + 9 + 46;
  CHECK(b[offsets] == '\x0e');
  CHECK(u64_at(b, offsets + 1) == 17);
  CHECK(b[offsets + 9] == '\x0b');
  CHECK(u64_at(b, offsets + 10) == 44);
  CHECK(u64_at(b, offsets + 18) == 55);
  const std::size_t footer = offsets + 26;
  CHECK(b[footer] == '\x02');
  CHECK(u64_at(b, footer + 1) == 20);
  CHECK(u64_at(b, footer + 9) == 44);
  CHECK(u64_at(b, footer + 17) == offsets);
  CHECK(u32_at(b, footer + 25) == mcap::crc32(std::string_view(b).substr(44, footer + 25 - 44)));
  CHECK(b.substr(footer + 29) == std::string("\x89MCAP0\r\n", 8));
  CHECK(b.size() == footer + 29 + 8);
  CHECK_NOTHROW(reader::read(b));
}

TEST_CASE("a message in a chunk, with its index, byte by byte", "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out, {"", "antkit", 1U << 20});
  const auto s = w.add_schema("foxglove.Log", "jsonschema", "{}");
  const auto c = w.add_channel(s, "/log", "json", {{"k", "v"}});
  CHECK(s == 1);
  CHECK(c == 1);
  w.write({c, 7, 1'500'000'000, 1'500'000'000, "{\"a\":1}"});
  w.finish();
  const std::string b = out.str();
  // Schema at 31: id 1, "foxglove.Log", "jsonschema", data "{}".
  CHECK(b[31] == '\x03');
  CHECK(u64_at(b, 32) == 2 + 4 + 12 + 4 + 10 + 4 + 2);
  const std::size_t channel = 31 + 9 + 38;
  CHECK(b[channel] == '\x04');
  // Channel: id 1, schema 1, "/log", "json", metadata {k: v} (10 bytes).
  CHECK(u64_at(b, channel + 1) == 2 + 2 + 8 + 8 + 4 + 10);
  const std::size_t chunk = channel + 9 + 34;
  REQUIRE(b[chunk] == '\x06');
  // Chunk: start, end, uncompressed size, CRC, compression "", records (one Message record).
  CHECK(u64_at(b, chunk + 9) == 1'500'000'000);
  CHECK(u64_at(b, chunk + 17) == 1'500'000'000);
  const std::uint64_t records = 9 + 2 + 4 + 8 + 8 + 7;
  CHECK(u64_at(b, chunk + 25) == records);
  CHECK(u32_at(b, chunk + 37) == 0); // compression ""
  CHECK(u64_at(b, chunk + 41) == records);
  const std::string_view message = std::string_view(b).substr(chunk + 49, records);
  CHECK(u32_at(b, chunk + 33) == mcap::crc32(message));
  CHECK(message[0] == '\x05');
  CHECK(message.substr(9 + 2 + 4 + 8 + 8) == "{\"a\":1}");
  // The MessageIndex after it: channel 1, one entry (time, offset 0 in the records).
  const std::size_t index = chunk + 49 + records;
  CHECK(b[index] == '\x07');
  CHECK(u64_at(b, index + 1) == 2 + 4 + 16);
  CHECK(u32_at(b, index + 11) == 16);
  CHECK(u64_at(b, index + 15) == 1'500'000'000);
  CHECK(u64_at(b, index + 23) == 0);
  CHECK(b[index + 31] == '\x0f'); // DataEnd

  const auto f = reader::read(b);
  REQUIRE(f.messages.size() == 1);
  CHECK(f.messages[0] == mcap::Message{c, 7, 1'500'000'000, 1'500'000'000, "{\"a\":1}"});
  CHECK(f.channels.at(1).metadata == std::vector<std::pair<std::string, std::string>>{{"k", "v"}});
  CHECK(f.schemas.at(1).name == "foxglove.Log");
  CHECK(f.indexed_messages == 1);
  CHECK(f.statistics.channel_counts == std::map<std::uint16_t, std::uint64_t>{{1, 1}});
}

TEST_CASE("mcap writer refuses a message on an unknown channel", "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out);
  CHECK_THROWS_AS(w.write({1, 0, 0, 0, ""}), std::logic_error);
  CHECK_THROWS_AS(w.add_channel(3, "/x", "json"), std::logic_error);
}

TEST_CASE("a message written in place is the same bytes as write()", "[io][mcap]") {
  // Small chunks, so that messages land in several and the data section's CRC (combined from
  // each chunk's) covers them all.
  const auto file = [](bool in_place) {
    std::ostringstream out;
    mcap::Writer w(out, {"", "antkit", 100});
    const auto s = w.add_schema("s", "jsonschema", "{}");
    const auto c = w.add_channel(s, "/c", "json");
    for (std::uint32_t k = 0; k < 20; ++k) {
      const std::string data(k * 7, static_cast<char>('a' + k));
      if (in_place) {
        w.begin_message(c, k, 10U * k, 10U * k + 1) += data;
        w.end_message();
      } else {
        w.write({c, k, 10U * k, 10U * k + 1, data});
      }
    }
    w.finish();
    return std::move(out).str();
  };
  const std::string a = file(true);
  CHECK(a == file(false));
  const auto f = reader::read(a);
  CHECK(f.messages.size() == 20);
  CHECK(f.messages[19].data == std::string(133, 't'));
}

TEST_CASE("mcap writer refuses calls between begin_message and end_message", "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out);
  const auto c = w.add_channel(0, "/c", "json");
  CHECK_THROWS_AS(w.end_message(), std::logic_error);
  w.begin_message(c, 0, 0, 0) += "x";
  CHECK_THROWS_AS(w.begin_message(c, 1, 0, 0), std::logic_error);
  CHECK_THROWS_AS(w.write({c, 1, 0, 0, ""}), std::logic_error);
  CHECK_THROWS_AS(w.add_channel(0, "/d", "json"), std::logic_error);
  CHECK_THROWS_AS(w.add_schema("s", "jsonschema", "{}"), std::logic_error);
  CHECK_THROWS_AS(w.finish(), std::logic_error);
  w.end_message();
  w.finish();
  CHECK(w.messages() == 1);
}

TEST_CASE("a damaged byte is caught by the reader's CRCs", "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out);
  const auto c = w.add_channel(0, "/x", "json");
  for (std::uint32_t i = 0; i < 10; ++i) w.write({c, i, i * 10U, i * 10U, "{\"i\":1}"});
  w.finish();
  const std::string b = out.str();
  REQUIRE_NOTHROW(reader::read(b));
  // Every byte of the file but the magics, flipped in turn, is refused.
  for (std::size_t at = 8; at + 8 < b.size(); ++at) {
    std::string d = b;
    d[at] = static_cast<char>(d[at] ^ 0x20);
    INFO(at);
    CHECK_THROWS(reader::read(d));
  }
}

TEST_CASE("mcap: any messages written are read back exactly, through every index", "[property]") {
  rc::prop("round trip", [] {
    const auto channels = *rc::gen::inRange<std::uint16_t>(1, 6);
    const auto chunk_size = *rc::gen::inRange<std::uint64_t>(1, 2000);
    const auto messages =
        *rc::gen::container<std::vector<mcap::Message>>(rc::gen::build<mcap::Message>(
            rc::gen::set(
                &mcap::Message::channel_id,
                rc::gen::inRange<std::uint16_t>(1, static_cast<std::uint16_t>(channels + 1))),
            rc::gen::set(&mcap::Message::sequence, rc::gen::arbitrary<std::uint32_t>()),
            rc::gen::set(&mcap::Message::log_time, rc::gen::arbitrary<std::uint64_t>()),
            rc::gen::set(&mcap::Message::publish_time, rc::gen::arbitrary<std::uint64_t>()),
            rc::gen::set(&mcap::Message::data, rc::gen::arbitrary<std::string>())));
    std::ostringstream out;
    mcap::Writer w(out, {"", "antkit", chunk_size});
    const auto schema = w.add_schema("s", "jsonschema", "{}");
    for (std::uint16_t i = 0; i < channels; ++i)
      w.add_channel(i % 2 == 0 ? schema : 0, "/t" + std::to_string(i), "json");
    for (const auto& m : messages) w.write(m);
    w.finish();
    const auto f = reader::read(out.str());
    RC_ASSERT(f.messages == messages);
    RC_ASSERT(f.indexed_messages == messages.size());
    RC_ASSERT(f.channels.size() == channels);
    // The same calls write the same bytes.
    std::ostringstream again;
    mcap::Writer w2(again, {"", "antkit", chunk_size});
    w2.add_schema("s", "jsonschema", "{}");
    for (std::uint16_t i = 0; i < channels; ++i)
      w2.add_channel(i % 2 == 0 ? schema : 0, "/t" + std::to_string(i), "json");
    for (const auto& m : messages) w2.write(m);
    w2.finish();
    RC_ASSERT(again.str() == out.str());
  });
}

TEST_CASE("mcap: chunks built apart are written as chunks, read back exactly", "[property]") {
  // Messages split at random into runs, each run either written through the writer or built in a
  // Chunk (sealed or not) and written with write_chunk: read back in order, through every index;
  // the same calls give the same bytes.
  rc::prop("round trip through chunks", [] {
    const auto channels = *rc::gen::inRange<std::uint16_t>(1, 6);
    const auto messages =
        *rc::gen::container<std::vector<mcap::Message>>(rc::gen::build<mcap::Message>(
            rc::gen::set(
                &mcap::Message::channel_id,
                rc::gen::inRange<std::uint16_t>(1, static_cast<std::uint16_t>(channels + 1))),
            rc::gen::set(&mcap::Message::sequence, rc::gen::arbitrary<std::uint32_t>()),
            rc::gen::set(&mcap::Message::log_time, rc::gen::inRange<std::uint64_t>(0, 50)),
            rc::gen::set(&mcap::Message::publish_time, rc::gen::arbitrary<std::uint64_t>()),
            rc::gen::set(&mcap::Message::data, rc::gen::arbitrary<std::string>())));
    // Per message: 0 through the writer, 1 into the chunk, 2 into the chunk and the chunk out.
    const auto how = *rc::gen::container<std::vector<int>>(messages.size(), rc::gen::inRange(0, 3));
    const auto seal = *rc::gen::arbitrary<bool>();
    const auto write = [&] {
      std::ostringstream out;
      mcap::Writer w(out, {"", "antkit", 700});
      for (std::uint16_t i = 0; i < channels; ++i) w.add_channel(0, "/t" + std::to_string(i), "");
      mcap::Chunk chunk;
      for (std::size_t i = 0; i < messages.size(); ++i) {
        if (how[i] == 0) {
          if (!chunk.empty()) {
            if (seal) chunk.seal();
            w.write_chunk(chunk);
            RC_ASSERT(chunk.empty());
          }
          w.write(messages[i]);
        } else {
          chunk.add(messages[i]);
          if (how[i] == 2) w.write_chunk(chunk);
        }
        RC_ASSERT(w.messages() + chunk.messages() == i + 1);
      }
      w.write_chunk(chunk);
      w.finish();
      return out.str();
    };
    const auto bytes = write();
    const auto f = reader::read(bytes);
    RC_ASSERT(f.messages == messages);
    RC_ASSERT(f.indexed_messages == messages.size());
    RC_ASSERT(f.statistics.message_count == messages.size());
    RC_ASSERT(write() == bytes);
  });
}

TEST_CASE("mcap: write_chunk refuses an unknown channel, an open message, a sealed chunk's "
          "message",
          "[io][mcap]") {
  std::ostringstream out;
  mcap::Writer w(out);
  w.add_channel(0, "/a", "json");
  mcap::Chunk c;
  CHECK_THROWS_AS(c.begin_message(0, 0, 0, 0), std::logic_error);
  c.add({2, 0, 0, 0, "x"}); // channel 2: not in the writer
  CHECK_THROWS_AS(w.write_chunk(c), std::logic_error);
  c.clear();
  c.begin_message(1, 0, 0, 0);
  CHECK_THROWS_AS(w.write_chunk(c), std::logic_error);
  CHECK_THROWS_AS(c.seal(), std::logic_error);
  c.end_message();
  c.seal();
  CHECK_THROWS_AS(c.add({1, 1, 1, 1, "y"}), std::logic_error);
  w.begin_message(1, 0, 0, 0);
  CHECK_THROWS_AS(w.write_chunk(c), std::logic_error);
  w.end_message();
  w.write_chunk(c);
  CHECK(c.empty());
  w.finish();
  const auto f = reader::read(out.str());
  CHECK(f.messages.size() == 2);
  CHECK(f.chunks == 2);
}
