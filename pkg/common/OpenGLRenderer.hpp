// The 3D view's settings (yade.qt.Renderer(), manual "3d view"): what is drawn and how. The drawing
// itself belongs to the GUI (gui/README.md); these settings exist in every build, so that a script that
// sets them runs headless too. Names and defaults are the reference's.
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

// Something a script adds to every frame (OpenGLRenderer.extraDrawers).
class GlExtraDrawer : public Serializable {
public:
    static constexpr const char* classDoc = "Something drawn in every frame besides the scene (OpenGLRenderer.extraDrawers).";
    bool dead = false;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("dead", dead, "Skip this drawer");
    }
};

class OpenGLRenderer : public Serializable {
public:
    static constexpr const char* classDoc =
        "Settings of the 3D view (yade.qt.Renderer()): which parts of the scene are drawn, lights, colors, scaling "
        "of displacements and rotations. They can be set without a display; the drawing needs the GUI.";
    Vector3r dispScale{1, 1, 1};
    Real rotScale = 1;
    Vector3r lightPos{75, 130, 0}, light2Pos{-130, 75, 30};
    Vector3r lightColor{0.6, 0.6, 0.6}, light2Color{0.5, 0.5, 0.1};
    Vector3r cellColor{1, 1, 0}, bgColor{0.2, 0.2, 0.2};
    bool wire = false, light1 = true, light2 = true, dof = false, id = false, bound = false, shape = true;
    bool intrWire = false, intrGeom = false, intrPhys = false, intrAllWire = false, ghosts = true;
    int mask = -1, selId = -1;
    std::vector<std::shared_ptr<GlExtraDrawer>> extraDrawers;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("dispScale", dispScale, "Scale of displacements from the reference positions (1: true positions)", Attr::finite);
        v.attr("rotScale", rotScale, "Scale of rotations from the reference orientations (1: true orientations)", Attr::finite);
        v.attr("lightPos", lightPos, "Position of the first light", Attr::finite);
        v.attr("light2Pos", light2Pos, "Position of the second light", Attr::finite);
        v.attr("lightColor", lightColor, "Color of the first light (RGB, 0-1)", Attr::finite);
        v.attr("light2Color", light2Color, "Color of the second light (RGB, 0-1)", Attr::finite);
        v.attr("cellColor", cellColor, "Color of the periodic cell (RGB, 0-1)", Attr::finite);
        v.attr("bgColor", bgColor, "Background color (RGB, 0-1)", Attr::finite);
        v.attr("wire", wire, "Draw every shape as wire frame");
        v.attr("light1", light1, "Turn the first light on");
        v.attr("light2", light2, "Turn the second light on");
        v.attr("dof", dof, "Show which degrees of freedom are blocked");
        v.attr("id", id, "Show the bodies' ids");
        v.attr("bound", bound, "Draw the bounding volumes");
        v.attr("shape", shape, "Draw the shapes");
        v.attr("intrWire", intrWire, "Draw interactions as wire frame");
        v.attr("intrGeom", intrGeom, "Draw the interactions' geometry");
        v.attr("intrPhys", intrPhys, "Draw the interactions' physics (force chains: Gl1_NormPhys)");
        v.attr("intrAllWire", intrAllWire, "Draw every interaction, contact or not, as a line");
        v.attr("ghosts", ghosts, "Draw the periodic images of bodies that stick out of the cell");
        v.attr("mask", mask, "Draw only the bodies whose groupMask shares a bit with this");
        v.attr("selId", selId, "Id of the selected body (-1: none)");
        v.attr("extraDrawers", extraDrawers, "Further things drawn in every frame (GlExtraDrawer)");
    }
};

} // namespace yade
