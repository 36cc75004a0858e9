// PatientPanel: the widgets follow panel::PatientPanelState. Signals are blocked while they are
// set, so that only a user's action requests a selection.
#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QIcon>
#include <QLabel>
#include <QList>
#include <QPair>
#include <QPixmap>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include "vicc_anatomy_viz/rviz/patient_panel.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

namespace {

QIcon swatch(const panel::CategoryItem& item) {
  QPixmap pixmap(14, 14);
  pixmap.fill(QColor::fromRgbF(item.red, item.green, item.blue));
  return QIcon(pixmap);
}

QString categoryText(const panel::CategoryItem& item) {
  return QString::fromStdString(item.label) + " (" + QString::number(item.count) + ")";
}

}  // namespace

void PatientPanel::refreshWidgets() {
  refreshPatients();
  refreshTimeline();
  refreshCategories();
  shown_label_->setText(
      state_.shown() ? "Shown: " + QString::fromStdString(panel::describeShown(*state_.shown()))
                     : QString("Shown: nothing yet"));
  if (state_.requestsInFlight() > 0) shown_label_->setText(shown_label_->text() + " (updating)");
}

void PatientPanel::refreshPatients() {
  QList<QPair<QString, QString>> items;  // label, patient id
  for (const auto& patient : state_.patients.patients()) {
    items.append({QString::fromStdString(panel::describePatient(patient)),
                  QString::fromStdString(patient.id)});
  }
  const std::string& selected = state_.patients.selected();
  if (!selected.empty() && !state_.patients.selectedIsListed()) {
    const QString id = QString::fromStdString(selected);
    items.append({id + (state_.patients.listed() ? " (not in the database)" : ""), id});
  }
  const QSignalBlocker blocker(patient_combo_);
  bool unchanged = patient_combo_->count() == items.size();
  for (int i = 0; unchanged && i < items.size(); ++i) {
    unchanged = patient_combo_->itemText(i) == items[i].first &&
                patient_combo_->itemData(i).toString() == items[i].second;
  }
  if (!unchanged) {  // rebuilding would close an open drop-down list
    patient_combo_->clear();
    for (const auto& [label, id] : items) patient_combo_->addItem(label, id);
  }
  patient_combo_->setCurrentIndex(
      selected.empty() ? -1 : patient_combo_->findData(QString::fromStdString(selected)));
}

void PatientPanel::refreshTimeline() {
  const QSignalBlocker slider_blocker(timeline_slider_);
  const QSignalBlocker latest_blocker(latest_box_);
  const std::size_t count = state_.timeline.size();
  timeline_slider_->setEnabled(count > 1);
  timeline_slider_->setRange(0, count > 0 ? static_cast<int>(count) - 1 : 0);
  const auto index = state_.timeline.sliderIndex();
  timeline_slider_->setValue(index ? static_cast<int>(*index) : 0);
  latest_box_->setEnabled(count > 0);
  latest_box_->setChecked(state_.timeline.followsLatest());
  timeline_label_->setText(QString::fromStdString(state_.timeline.describe()));
}

void PatientPanel::refreshCategories() {
  const auto& legend = state_.categories.legend();
  bool same_ids = legend.size() == category_boxes_.size();
  for (const auto& item : legend) same_ids = same_ids && category_boxes_.count(item.id);
  if (!same_ids) {
    for (auto& [id, box] : category_boxes_) delete box;
    category_boxes_.clear();
    for (const auto& item : legend) {
      auto* box = new QCheckBox;
      box->setObjectName(QString::fromStdString("category_" + item.id));
      const QString id = QString::fromStdString(item.id);
      connect(box, &QCheckBox::toggled, this,
              [this, id](bool checked) { onCategoryToggled(id, checked); });
      categories_layout_->addWidget(box);
      category_boxes_[item.id] = box;
    }
  }
  for (const auto& item : legend) {
    QCheckBox* box = category_boxes_.at(item.id);
    const QSignalBlocker blocker(box);
    box->setText(categoryText(item));
    box->setIcon(swatch(item));
    box->setChecked(state_.categories.isVisible(item.id));
  }
}

}  // namespace vicc_anatomy_viz::rviz_plugin
