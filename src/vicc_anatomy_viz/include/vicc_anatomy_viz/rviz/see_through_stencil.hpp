#pragma once
// View-dependent transparency per pixel (thesis 4.4.2.2, Fig. 4.3) in one extra pass: after
// the opaque skin and the skin marks, the depth buffer is cleared and the encoded inner
// structures are drawn blended over what hides them (among themselves depth-tested), marking
// their pixels in the stencil buffer; the unencoded structures that lie in front of them
// (faded, per object) are drawn only inside the marked pixels. So the skin becomes
// semi-transparent exactly where it hides an encoded structure from the current camera and
// keeps its context everywhere else, and no skin pixel is drawn twice. Set up per render
// queue group. The depth clear comes after rviz's main queue: an object of another display in
// front of an encoded structure does not hide it (the structure shows through it as through
// the skin).

#include <OGRE/OgreRenderQueueListener.h>

namespace vicc_anatomy_viz::rviz_plugin {

class SeeThroughStencil : public Ogre::RenderQueueListener {
 public:
  /// Whether the encoded inner structures are drawn over what hides them; if not, they are
  /// not drawn at all (the opaque skin hides them).
  void setEnabled(bool enabled) { enabled_ = enabled; }
  void renderQueueStarted(Ogre::uint8 queue, const Ogre::String& invocation, bool& skip) override;
  void renderQueueEnded(Ogre::uint8 queue, const Ogre::String& invocation, bool& repeat) override;

 private:
  bool enabled_ = true;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
