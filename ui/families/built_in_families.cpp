#include "families/built_in_families.h"

#include <QDockWidget>

namespace imudesk::ui {

void registerBuiltInFamilies(FamilyUiRegistry &registry)
{
    registry.add(std::make_unique<HipnucSerialUi>());
    registry.add(std::make_unique<Hec495SerialUi>());
    registry.add(std::make_unique<ModbusUi>());
    registry.add(std::make_unique<CanUi>());
    registry.add(std::make_unique<ReplayUi>());
}

QDockWidget *familyDock(QWidget *content, const QString &objectName, const QString &title)
{
    auto *dock = new QDockWidget(title);
    dock->setObjectName(objectName);
    dock->setWidget(content);
    return dock;
}

} // namespace imudesk::ui
