#pragma once
// Per-pixel view-dependent transparency of the skin (thesis 4.4.2.2, Fig. 4.3): the encoded
// inner structures mark the pixels they cover in the stencil buffer; the opaque skin is drawn
// only outside the marked pixels, a see-through copy of the skin only inside them. So the skin
// becomes semi-transparent exactly where it hides an encoded structure from the current
// camera, and keeps its context everywhere else. Set up per render queue group.

#include <OGRE/OgreRenderQueueListener.h>

namespace vicc_anatomy_viz::rviz_plugin {

class SeeThroughStencil : public Ogre::RenderQueueListener {
 public:
  void setEnabled(bool enabled) { enabled_ = enabled; }
  void renderQueueStarted(Ogre::uint8 queue, const Ogre::String& invocation, bool& skip) override;
  void renderQueueEnded(Ogre::uint8 queue, const Ogre::String& invocation, bool& repeat) override;

 private:
  bool enabled_ = true;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
