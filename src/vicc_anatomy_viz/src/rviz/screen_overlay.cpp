#include "vicc_anatomy_viz/rviz/screen_overlay.hpp"

#include <OGRE/OgreHardwarePixelBuffer.h>
#include <OGRE/OgreMaterialManager.h>
#include <OGRE/OgreTechnique.h>
#include <OGRE/OgreTextureManager.h>
#include <OGRE/Overlay/OgreOverlay.h>
#include <OGRE/Overlay/OgreOverlayManager.h>
#include <OGRE/Overlay/OgrePanelOverlayElement.h>

#include <QFont>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>

#include <algorithm>

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

const Ogre::String& kGroup = Ogre::ResourceGroupManager::DEFAULT_RESOURCE_GROUP_NAME;
constexpr int kPadding = 8;
constexpr int kSwatch = 14;

QImage paint(const std::vector<OverlayLine>& lines) {
  QFont font("DejaVu Sans", 9);
  QFont bold = font;
  bold.setBold(true);
  const QFontMetrics metrics(bold);
  int width = 0;
  for (const OverlayLine& line : lines)
    width = std::max(width, metrics.horizontalAdvance(QString::fromStdString(line.text)) +
                                (line.has_swatch ? kSwatch + 6 : 0));
  const int line_height = std::max(metrics.height(), kSwatch) + 3;
  QImage image(width + 2 * kPadding, static_cast<int>(lines.size()) * line_height + 2 * kPadding,
               QImage::Format_ARGB32_Premultiplied);
  image.fill(QColor(255, 255, 255, 225));
  QPainter painter(&image);
  painter.setPen(QColor(40, 40, 40));
  int y = kPadding;
  for (const OverlayLine& line : lines) {
    int x = kPadding;
    if (line.has_swatch) {
      painter.fillRect(x, y + 1, kSwatch, kSwatch,
                       QColor::fromRgbF(line.swatch.r, line.swatch.g, line.swatch.b));
      x += kSwatch + 6;
    }
    painter.setFont(line.bold ? bold : font);
    painter.drawText(x, y, width, line_height, Qt::AlignLeft | Qt::AlignVCenter,
                     QString::fromStdString(line.text));
    y += line_height;
  }
  return image;
}

}  // namespace

ScreenOverlay::ScreenOverlay(const std::string& name, Corner corner)
    : name_(name), corner_(corner) {
  Ogre::OverlayManager& manager = Ogre::OverlayManager::getSingleton();
  overlay_ = manager.create(name_);
  panel_ = static_cast<Ogre::PanelOverlayElement*>(
      manager.createOverlayElement("Panel", name_ + "/panel"));
  panel_->setMetricsMode(Ogre::GMM_PIXELS);
  material_ = Ogre::MaterialManager::getSingleton().create(name_ + "/material", kGroup);
  Ogre::Pass& pass = *material_->getTechnique(0)->getPass(0);
  pass.setLightingEnabled(false);
  pass.setSceneBlending(Ogre::SBT_TRANSPARENT_ALPHA);
  pass.setDepthCheckEnabled(false);
  overlay_->add2D(panel_);
  overlay_->hide();
}

ScreenOverlay::~ScreenOverlay() {
  Ogre::OverlayManager& manager = Ogre::OverlayManager::getSingleton();
  overlay_->remove2D(panel_);
  manager.destroyOverlayElement(panel_);
  manager.destroy(overlay_);
  Ogre::MaterialManager::getSingleton().remove(material_);
  if (texture_) Ogre::TextureManager::getSingleton().remove(texture_);
}

void ScreenOverlay::setLines(const std::vector<OverlayLine>& lines) {
  has_lines_ = !lines.empty();
  setVisible(visible_);
  if (!has_lines_) return;
  const QImage image = paint(lines);
  if (texture_) Ogre::TextureManager::getSingleton().remove(texture_);
  static unsigned generation = 0;
  texture_ = Ogre::TextureManager::getSingleton().createManual(
      name_ + "/texture/" + std::to_string(++generation), kGroup, Ogre::TEX_TYPE_2D,
      static_cast<Ogre::uint>(image.width()), static_cast<Ogre::uint>(image.height()), 0,
      Ogre::PF_A8R8G8B8, Ogre::TU_DEFAULT);
  const Ogre::PixelBox box(image.width(), image.height(), 1, Ogre::PF_A8R8G8B8,
                           const_cast<uchar*>(image.constBits()));
  texture_->getBuffer()->blitFromMemory(box);
  Ogre::Pass& pass = *material_->getTechnique(0)->getPass(0);
  pass.removeAllTextureUnitStates();
  pass.createTextureUnitState()->setTexture(texture_);
  material_->load();
  panel_->setMaterialName(material_->getName());
  panel_->setDimensions(image.width(), image.height());
  const int margin = 10;
  if (corner_ == Corner::kTopLeft) {
    panel_->setVerticalAlignment(Ogre::GVA_TOP);
    panel_->setPosition(margin, margin);
  } else {
    panel_->setVerticalAlignment(Ogre::GVA_BOTTOM);
    panel_->setPosition(margin, -margin - image.height());
  }
}

void ScreenOverlay::setVisible(bool visible) {
  visible_ = visible;
  if (visible_ && has_lines_)
    overlay_->show();
  else
    overlay_->hide();
}

}  // namespace vicc_anatomy_viz::rviz_plugin
