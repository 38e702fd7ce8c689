// libFuzzer target: import of the vendor's HI91 CSV (decode/hipnuc_vendor_csv_reader.h).
//
// Whatever the bytes, the import must not crash. Samples plus malformed lines never exceed
// the lines of the input; reported errors carry increasing line numbers inside the input and
// at most kMaxReportedErrors are kept; every sample is an HI91 sample with finite-or-parsed
// values from the row (no NaN introduced by the importer itself unless the text said "nan").
#include "decode/hipnuc_vendor_csv_reader.h"

#include <QBuffer>
#include <QByteArray>

#include <cstdint>
#include <cstdio>

#define FUZZ_CHECK(cond)                                                                              \
    do {                                                                                              \
        if (!(cond)) {                                                                                \
            std::fprintf(stderr, "fuzz_vendor_csv: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                         \
        }                                                                                             \
    } while (0)

using imudesk::decode::VendorCsvImporter;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer buf(&bytes);
    buf.open(QIODevice::ReadOnly);
    uint64_t samples = 0;
    const auto r = VendorCsvImporter::read(buf, [&](const imudesk::model::Sample &s) {
        FUZZ_CHECK(s.source == "HI91");
        ++samples;
    });
    const uint64_t lines = uint64_t(bytes.count('\n')) + 1;
    FUZZ_CHECK(samples == r.samples);
    if (!r.ok) {
        FUZZ_CHECK(!r.error.isEmpty());
        FUZZ_CHECK(r.samples == 0);
        return 0;
    }
    FUZZ_CHECK(r.samples + r.badLines < lines + 1);
    FUZZ_CHECK(r.errors.size() <= VendorCsvImporter::kMaxReportedErrors);
    FUZZ_CHECK(r.errors.size() <= r.badLines);
    uint64_t previous = 0;
    for (const auto &e : r.errors) {
        FUZZ_CHECK(e.line > previous && e.line <= lines);
        FUZZ_CHECK(!e.message.isEmpty());
        previous = e.line;
    }
    return 0;
}
