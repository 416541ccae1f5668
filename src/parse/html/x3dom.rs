//! What X3DOM reads that X3D does not have: its own node types and the attributes of its
//! `<x3d>` element and of nodes. From X3DOM's source (github.com/x3dom/x3dom: the node
//! types of `build/core/packages.json` and `src/nodes/`, registered with
//! `x3dom.registerNodeType`; the `<x3d>` attributes `src/X3DCanvas.js` reads; the
//! parameters of `<param>` that `src/util/Properties.js` users read), less the X3D
//! names (the test below keeps them apart). All names are lower case, as an HTML parser
//! gives them.

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

/// Fields X3DOM adds to X3D node types (e.g. `render` on every bounded node, `zNear` on
/// viewpoints, `nameSpaceName` and `mapDEFToID` on Inline, `lit` on geometry), which no X3D
/// node type has.
pub const NODE_ATTRIBUTES: &[&str] = &[
    "render",
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
            assert_eq!(names::attribute("Shape", attribute), None, "{attribute}");
        }
        assert!(NODES.windows(2).all(|w| w[0] < w[1]));
    }
}
