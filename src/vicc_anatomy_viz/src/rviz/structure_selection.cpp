#include "vicc_anatomy_viz/rviz/structure_selection.hpp"

#include <rviz/properties/property.h>
#include <rviz/properties/string_property.h>

#include <sstream>

namespace vicc_anatomy_viz::rviz_plugin {

StructureSelectionHandler::StructureSelectionHandler(
    rviz::DisplayContext* context, std::string title, std::string text,
    std::function<void(const std::string&)> on_select)
    : rviz::SelectionHandler(context),
      title_(std::move(title)),
      text_(std::move(text)),
      on_select_(std::move(on_select)) {}

void StructureSelectionHandler::createProperties(const rviz::Picked& /*picked*/,
                                                 rviz::Property* parent) {
  auto* group = new rviz::Property(QString::fromStdString(title_), QVariant(), "", parent);
  properties_.push_back(group);
  std::istringstream lines(text_);
  std::string line;
  int index = 0;
  while (std::getline(lines, line)) {
    auto* entry =
        new rviz::StringProperty(QString::number(++index), QString::fromStdString(line), "", group);
    entry->setReadOnly(true);
  }
  group->expand();
}

void StructureSelectionHandler::onSelect(const rviz::Picked& picked) {
  rviz::SelectionHandler::onSelect(picked);
  if (on_select_) on_select_(text_.empty() ? title_ : text_);
}

void StructureSelectionHandler::onDeselect(const rviz::Picked& picked) {
  rviz::SelectionHandler::onDeselect(picked);
  if (on_select_) on_select_("");
}

}  // namespace vicc_anatomy_viz::rviz_plugin
