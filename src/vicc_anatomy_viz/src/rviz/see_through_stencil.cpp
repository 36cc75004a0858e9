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
  // rviz's selection renders the scene with the "Pick..." material schemes: without the faded
  // occluders there, a click on a see-through part reaches the encoded structure the user sees.
  const bool picking =
      Ogre::MaterialManager::getSingleton().getActiveScheme().rfind("Pick", 0) == 0;
  if (queue == kOccluderQueue) skip = !enabled_ || picking;
  // Not see-through, the opaque skin hides every inner structure: llvmpipe would still
  // rasterise (and bin) each of them only to fail the depth test.
  if (queue == kEncodedQueue) skip = !enabled_;
  if (!enabled_) return;
  if (queue == kEncodedQueue) {
    // Depth and stencil share one buffer: clearing both is one plain clear.
    Ogre::Root::getSingleton().getRenderSystem()->clearFrameBuffer(
        Ogre::FBT_DEPTH | Ogre::FBT_STENCIL, Ogre::ColourValue::Black, 1.f, 0);
    setStencil(Ogre::CMPF_ALWAYS_PASS, Ogre::SOP_REPLACE);
  } else if (queue == kOccluderQueue) {
    setStencil(Ogre::CMPF_EQUAL, Ogre::SOP_KEEP);
  }
}

void SeeThroughStencil::renderQueueEnded(Ogre::uint8 queue, const Ogre::String& /*invocation*/,
                                         bool& /*repeat*/) {
  if (queue == kEncodedQueue || queue == kOccluderQueue)
    Ogre::Root::getSingleton().getRenderSystem()->setStencilCheckEnabled(false);
}

}  // namespace vicc_anatomy_viz::rviz_plugin
