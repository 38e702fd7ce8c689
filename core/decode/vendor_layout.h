#pragma once
// A family's own file layout for its records, where its vendor's tool writes one (HiPNUC's
// CSV: a file per frame type, decode/hipnuc_vendor_csv.h). An export in the vendor's layout
// asks the capture's family for it (vendorLayoutFor) and hands it each record its decoder
// made; a family without one has none, and its records are skipped (and counted).
#include "decode/stream_decoder.h"

#include <QString>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace imudesk::decode {

class VendorLayout {
public:
    // Cells an imported row had that its record cannot give back (the converter keeps them in
    // the capture beside the record; the export writes them back): header name, cell text.
    using Cells = std::vector<std::pair<std::string, std::string>>;

    virtual ~VendorLayout() = default;
    // The file a record's row goes to: its type (the file's suffix: "HI91"; a string the layout
    // keeps, shared, not made per row) and the header line; false when the layout has no row for
    // the record.
    virtual bool fileOf(const Record &record, QString &type, const char *&header) const = 0;
    // The record's row, pcCounterMs in its time column; `keep` overrides the cells it names.
    virtual void appendRow(std::string &out, const Record &record, double pcCounterMs, const Cells &keep) const = 0;
    // The kept cells as the capture stores them, back.
    virtual Cells decodeCells(std::string_view text) const = 0;
};

// The layout of a family ("HiPNUC serial"), null when its vendor has none ImuDesk writes.
const VendorLayout *vendorLayoutFor(const std::string &family);

} // namespace imudesk::decode
