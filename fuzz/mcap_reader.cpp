// Fuzz target: the MCAP reader (io/mcap_reader.hpp), every message of any input read in order. Any
// input is read to its end or refused with InputError; the CRCs are not checked on the first pass
// (a mutated file would rarely get past them), and are on the second. Each message's data lies
// within the input or the reader's chunk buffer, and names a channel it read.
#include <antkit/io/mcap_reader.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  for (const bool crcs : {false, true}) {
    try {
      antkit::io::mcap::Reader reader(bytes, "fuzz.mcap", {crcs});
      antkit::io::mcap::MessageView m;
      std::uint64_t sum = 0;
      while (reader.next(m)) {
        if (m.channel == nullptr || !reader.channels().contains(m.channel->id)) std::abort();
        for (const char c : m.data) sum += static_cast<unsigned char>(c); // touched: ASan checks
      }
      (void)sum;
    } catch (const antkit::kernel::InputError&) {
    }
  }
  return 0;
}
