#pragma once
// The family UI plug-ins a test's window shows links with: the built-in ones, registered as
// app/gui/main.cpp registers them (the window registers none itself), alive for the process.
#include "families/built_in_families.h"

namespace imudesk::test {

inline const ui::FamilyUiRegistry &builtInFamilies()
{
    static const ui::FamilyUiRegistry registry = [] {
        ui::FamilyUiRegistry r;
        ui::registerBuiltInFamilies(r);
        return r;
    }();
    return registry;
}

} // namespace imudesk::test
