// The serial families ImuDesk knows, in detection order: one line each.
#include "links/serial_family.h"

#include <algorithm>

namespace imudesk::device {

const SerialFamilyKind &hipnucSerialKind(); // hipnuc_serial_kind.cpp
const SerialFamilyKind &hec495SerialKind(); // hec495_serial_kind.cpp

const std::vector<const SerialFamilyKind *> &serialFamilies()
{
    static const std::vector<const SerialFamilyKind *> families = {
        &hipnucSerialKind(),
        &hec495SerialKind(),
    };
    return families;
}

const SerialFamilyKind *serialFamily(const QString &id)
{
    for (const SerialFamilyKind *f : serialFamilies())
        if (f->id() == id)
            return f;
    return nullptr;
}

const std::vector<int> &serialDetectionBauds()
{
    static const std::vector<int> bauds = [] {
        std::vector<int> all;
        for (const SerialFamilyKind *f : serialFamilies())
            for (int b : f->bauds())
                if (std::find(all.begin(), all.end(), b) == all.end())
                    all.push_back(b);
        return all;
    }();
    return bauds;
}

} // namespace imudesk::device
