#pragma once
// Clicking an encoded structure with rviz's Select tool: the selection panel lists its name
// and raw values, and the display shows them as a text overlay (thesis Fig. 4.7C).

#include <functional>
#include <string>

#ifndef Q_MOC_RUN
#include <rviz/selection/selection_handler.h>
#endif

namespace vicc_anatomy_viz::rviz_plugin {

class StructureSelectionHandler : public rviz::SelectionHandler {
 public:
  /// `on_select` receives the overlay text when picked and "" when deselected.
  StructureSelectionHandler(rviz::DisplayContext* context, std::string title, std::string text,
                            std::function<void(const std::string&)> on_select);

  void createProperties(const rviz::Picked& picked, rviz::Property* parent) override;
  void onSelect(const rviz::Picked& picked) override;
  void onDeselect(const rviz::Picked& picked) override;

 private:
  std::string title_;
  std::string text_;
  std::function<void(const std::string&)> on_select_;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
