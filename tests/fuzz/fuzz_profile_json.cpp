// libFuzzer target: configuration profile loader (core/settings/config_profile.h).
//
// Whatever the bytes, loading must not crash. When a profile loads, every key is a known
// setting, every value is canonical (normalising it again gives the same text), and
// writing the profile out and loading it again gives the same settings.
#include "settings/config_profile.h"
#include "settings/setting_catalog.h"

#include <QByteArray>

#include <cstddef>
#include <cstdint>
#include <cstdio>

#define FUZZ_CHECK(cond)                                                                               \
    do {                                                                                               \
        if (!(cond)) {                                                                                 \
            std::fprintf(stderr, "fuzz_profile_json: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                          \
        }                                                                                              \
    } while (0)

using namespace imudesk::settings;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const auto profile = ConfigProfile::fromJson(bytes, &error);
    if (!profile) {
        FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    FUZZ_CHECK(size <= size_t(ConfigProfile::kMaxBytes));
    for (const auto &[key, value] : profile->settings) {
        const SettingDefinition *d = SettingCatalog::find(key);
        FUZZ_CHECK(d != nullptr);
        QString why;
        const auto again = SettingCatalog::normalize(*d, value, nullptr, &why);
        FUZZ_CHECK(again.has_value());
        FUZZ_CHECK(*again == value);
    }
    const auto round = ConfigProfile::fromJson(profile->toJson(), &error);
    FUZZ_CHECK(round.has_value());
    FUZZ_CHECK(round->settings == profile->settings);
    FUZZ_CHECK(round->product == profile->product && round->serial == profile->serial);
    return 0;
}
