#include "vicc_anatomy_viz/rviz/see_through_stencil.hpp"

#include <OGRE/OgreMaterialManager.h>
#include <OGRE/OgreRenderSystem.h>
#include <OGRE/OgreRoot.h>

#include "vicc_anatomy_viz/rviz/avatar_materials.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

constexpr Ogre::uint32 kMark = 1;

void setStencil(Ogre::CompareFunction compare, Ogre::StencilOperation pass_operation) {
  Ogre::StencilState state;
  state.enabled = true;
  state.compareOp = compare;
  state.referenceValue = kMark;
  state.depthStencilPassOp = pass_operation;
  Ogre::Root::getSingleton().getRenderSystem()->setStencilState(state);
}

}  // namespace

void SeeThroughStencil::renderQueueStarted(Ogre::uint8 queue, const Ogre::String& /*invocation*/,
                                           bool& skip) {
  Ogre::RenderSystem& render_system = *Ogre::Root::getSingleton().getRenderSystem();
  // rviz's selection renders the scene with the "Pick..." material schemes, painting what has
  // no pick handle (the skin) black: without the see-through skin there, a click on the
  // see-through part reaches the encoded structure the user sees.
  const bool picking =
      Ogre::MaterialManager::getSingleton().getActiveScheme().rfind("Pick", 0) == 0;
  if (queue == kSkinSeeThroughQueue) skip = !enabled_ || picking;
  if (!enabled_) return;
  switch (queue) {
    case kEncodedQueue:
      render_system.clearFrameBuffer(Ogre::FBT_STENCIL, Ogre::ColourValue::Black, 1.f, 0);
      setStencil(Ogre::CMPF_ALWAYS_PASS, Ogre::SOP_REPLACE);
      break;
    case kSkinQueue:
      setStencil(Ogre::CMPF_NOT_EQUAL, Ogre::SOP_KEEP);
      break;
    case kSkinSeeThroughQueue:
      setStencil(Ogre::CMPF_EQUAL, Ogre::SOP_KEEP);
      break;
    default:
      break;
  }
}

void SeeThroughStencil::renderQueueEnded(Ogre::uint8 queue, const Ogre::String& /*invocation*/,
                                         bool& /*repeat*/) {
  if (queue == kEncodedQueue || queue == kSkinQueue || queue == kSkinSeeThroughQueue)
    Ogre::Root::getSingleton().getRenderSystem()->setStencilCheckEnabled(false);
}

}  // namespace vicc_anatomy_viz::rviz_plugin
