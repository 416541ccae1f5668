//! What X3DOM reads that X3D does not have: its own node types and the attributes of its
//! `<x3d>` element and of nodes. From X3DOM's source (github.com/x3dom/x3dom: the node
//! types of `build/core/packages.json` and `src/nodes/`, registered with
//! `x3dom.registerNodeType`; the `<x3d>` attributes `src/X3DCanvas.js` reads; the
//! parameters of `<param>` that `src/util/Properties.js` users read), less the X3D
//! names (the test below keeps them apart). All names are lower case, as an HTML parser
//! gives them.
//!
//! The field names are looked up after the node type's own X3D fields and before any
//! other X3D field name: `isPickable` is X3DOM's field of Shape (its X3DShapeNode:
//! `this.addField_SFBool( ctx, "isPickable", true )`) and X3D's of Layer only, so on a
//! Shape it is X3DOM's.

/// X3DOM node types that are no X3D node type.
pub const NODES: &[&str] = &[
    "binarygeometry",
    "bitlodgeocomponent",
    "bitlodgeometry",
    "blendmode",
    "block",
    "bufferaccessor",
    "buffergeometry",
    "buffergeometryaccessor",
    "bufferview",
    "bvhrefiner",
    "colormaskmode",
    "commonsurfaceshader",
    "depthmode",
    "dish",
    "dynamiclod",
    "environment",
    "externalgeometry",
    "imagegeometry",
    "imagetextureatlas",
    "matrixtexturetransform",
    "matrixtransform",
    "mesh",
    "mprplane",
    "mprvolumestyle",
    "multipart",
    "nozzle",
    "param",
    "particleset",
    "patch",
    "physicalenvironmentlight",
    "plane",
    "popgeometry",
    "popgeometrylevel",
    "pyramid",
    "radarvolumestyle",
    "rectangulartorus",
    "refinementtexture",
    "remoteselectiongroup",
    "slopedcylinder",
    "snout",
    "solidofrevolution",
    "spheresegment",
    "surfaceshadertexture",
    "texture",
    "torus",
    "uniform",
    "viewfrustum",
];

/// Attributes X3DOM reads on its `<x3d>` element (X3DCanvas.js), beyond HTML's own.
pub const ROOT_ATTRIBUTES: &[&str] = &[
    "altimg",
    "backend",
    "disabledoubleclick",
    "disablekeys",
    "disableleftdrag",
    "disablemiddledrag",
    "disablerightdrag",
    "height",
    "keysenabled",
    "mapdeftoid",
    "primitivequality",
    "runtimeenabled",
    "showlog",
    "showprogress",
    "showstat",
    "showtouchpoints",
    "swfpath",
    "width",
];

/// X3DOM node types that have the name of an X3D 4.1 node type but are X3DOM's own, with
/// other fields: X3DOM's RenderedTexture is instantreality's (`viewpoint`, `background`,
/// `fog`, `scene`, `excludeNodes`, `dimensions`, `update`: its `registerNodeType(
/// "RenderedTexture", "Texturing", …)`), X3D 4.1's renders a URL-less texture with
/// `updateInterval`, `width`, `height`. In an X3DOM island they are X3DOM's.
pub const RENAMED_NODES: &[&str] = &["renderedtexture"];

/// Fields X3DOM adds to X3D node types (e.g. `render` on every bounded node, `zNear` on
/// viewpoints, `nameSpaceName` and `mapDEFToID` on Inline, `lit` on geometry,
/// `isPickable` on Shape), which these node types do not have in X3D.
pub const NODE_ATTRIBUTES: &[&str] = &[
    "render",
    "ispickable",
    "sortkey",
    "sorttype",
    "idmap",
    "znear",
    "zfar",
    "typeparams",
    "explorationmode",
    "shadowfiltersize",
    "shadowmapsize",
    "shadowoffset",
    "shadowcascades",
    "shadowsplitfactor",
    "shadowsplitoffset",
    "shadowexcludetransparentobjects",
    "lit",
    "namespacename",
    "mapdeftoid",
];

/// Whether `name` (lower case) is an attribute X3DOM gives a meaning on an element
/// (`root`: the `<x3d>` element) where X3D gives it none. Event handler attributes
/// (`onclick`) are HTML's, which X3DOM dispatches to on its nodes.
pub fn is_attribute(name: &str, root: bool) -> bool {
    (root && ROOT_ATTRIBUTES.contains(&name))
        || NODE_ATTRIBUTES.contains(&name)
        || (name.starts_with("on") && name.len() > 2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::html::names;

    #[test]
    fn no_x3dom_name_is_an_x3d_name() {
        for node in NODES {
            assert_eq!(names::element(node), None, "{node} is an X3D name");
        }
        for attribute in NODE_ATTRIBUTES {
            for node in [
                "Shape",
                "Transform",
                "Inline",
                "Viewpoint",
                "Material",
                "Box",
            ] {
                assert!(
                    names::own_field(node, attribute).is_none(),
                    "{node} {attribute}"
                );
            }
        }
        assert!(NODES.windows(2).all(|w| w[0] < w[1]));
    }
}
