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

/// The colour names X3DOM reads in an SFColor or SFColorRGBA (the table of its
/// `SFColor.colorParse` and `SFColorRGBA.colorParse`, `src/fields.js`: the X11 names, with
/// `feldspar`, `lightslateblue` and `violetred`, `lightgrey` but not `lightgray`), as
/// 0xRRGGBB, sorted by name. Lower case only: X3DOM looks the value up as written.
pub const COLOR_NAMES: &[(&str, u32)] = &[
    ("aliceblue", 0xf0f8ff),
    ("antiquewhite", 0xfaebd7),
    ("aqua", 0x00ffff),
    ("aquamarine", 0x7fffd4),
    ("azure", 0xf0ffff),
    ("beige", 0xf5f5dc),
    ("bisque", 0xffe4c4),
    ("black", 0x000000),
    ("blanchedalmond", 0xffebcd),
    ("blue", 0x0000ff),
    ("blueviolet", 0x8a2be2),
    ("brown", 0xa52a2a),
    ("burlywood", 0xdeb887),
    ("cadetblue", 0x5f9ea0),
    ("chartreuse", 0x7fff00),
    ("chocolate", 0xd2691e),
    ("coral", 0xff7f50),
    ("cornflowerblue", 0x6495ed),
    ("cornsilk", 0xfff8dc),
    ("crimson", 0xdc143c),
    ("cyan", 0x00ffff),
    ("darkblue", 0x00008b),
    ("darkcyan", 0x008b8b),
    ("darkgoldenrod", 0xb8860b),
    ("darkgray", 0xa9a9a9),
    ("darkgreen", 0x006400),
    ("darkkhaki", 0xbdb76b),
    ("darkmagenta", 0x8b008b),
    ("darkolivegreen", 0x556b2f),
    ("darkorange", 0xff8c00),
    ("darkorchid", 0x9932cc),
    ("darkred", 0x8b0000),
    ("darksalmon", 0xe9967a),
    ("darkseagreen", 0x8fbc8f),
    ("darkslateblue", 0x483d8b),
    ("darkslategray", 0x2f4f4f),
    ("darkturquoise", 0x00ced1),
    ("darkviolet", 0x9400d3),
    ("deeppink", 0xff1493),
    ("deepskyblue", 0x00bfff),
    ("dimgray", 0x696969),
    ("dodgerblue", 0x1e90ff),
    ("feldspar", 0xd19275),
    ("firebrick", 0xb22222),
    ("floralwhite", 0xfffaf0),
    ("forestgreen", 0x228b22),
    ("fuchsia", 0xff00ff),
    ("gainsboro", 0xdcdcdc),
    ("ghostwhite", 0xf8f8ff),
    ("gold", 0xffd700),
    ("goldenrod", 0xdaa520),
    ("gray", 0x808080),
    ("green", 0x008000),
    ("greenyellow", 0xadff2f),
    ("honeydew", 0xf0fff0),
    ("hotpink", 0xff69b4),
    ("indianred", 0xcd5c5c),
    ("indigo", 0x4b0082),
    ("ivory", 0xfffff0),
    ("khaki", 0xf0e68c),
    ("lavender", 0xe6e6fa),
    ("lavenderblush", 0xfff0f5),
    ("lawngreen", 0x7cfc00),
    ("lemonchiffon", 0xfffacd),
    ("lightblue", 0xadd8e6),
    ("lightcoral", 0xf08080),
    ("lightcyan", 0xe0ffff),
    ("lightgoldenrodyellow", 0xfafad2),
    ("lightgreen", 0x90ee90),
    ("lightgrey", 0xd3d3d3),
    ("lightpink", 0xffb6c1),
    ("lightsalmon", 0xffa07a),
    ("lightseagreen", 0x20b2aa),
    ("lightskyblue", 0x87cefa),
    ("lightslateblue", 0x8470ff),
    ("lightslategray", 0x778899),
    ("lightsteelblue", 0xb0c4de),
    ("lightyellow", 0xffffe0),
    ("lime", 0x00ff00),
    ("limegreen", 0x32cd32),
    ("linen", 0xfaf0e6),
    ("magenta", 0xff00ff),
    ("maroon", 0x800000),
    ("mediumaquamarine", 0x66cdaa),
    ("mediumblue", 0x0000cd),
    ("mediumorchid", 0xba55d3),
    ("mediumpurple", 0x9370d8),
    ("mediumseagreen", 0x3cb371),
    ("mediumslateblue", 0x7b68ee),
    ("mediumspringgreen", 0x00fa9a),
    ("mediumturquoise", 0x48d1cc),
    ("mediumvioletred", 0xc71585),
    ("midnightblue", 0x191970),
    ("mintcream", 0xf5fffa),
    ("mistyrose", 0xffe4e1),
    ("moccasin", 0xffe4b5),
    ("navajowhite", 0xffdead),
    ("navy", 0x000080),
    ("oldlace", 0xfdf5e6),
    ("olive", 0x808000),
    ("olivedrab", 0x6b8e23),
    ("orange", 0xffa500),
    ("orangered", 0xff4500),
    ("orchid", 0xda70d6),
    ("palegoldenrod", 0xeee8aa),
    ("palegreen", 0x98fb98),
    ("paleturquoise", 0xafeeee),
    ("palevioletred", 0xd87093),
    ("papayawhip", 0xffefd5),
    ("peachpuff", 0xffdab9),
    ("peru", 0xcd853f),
    ("pink", 0xffc0cb),
    ("plum", 0xdda0dd),
    ("powderblue", 0xb0e0e6),
    ("purple", 0x800080),
    ("red", 0xff0000),
    ("rosybrown", 0xbc8f8f),
    ("royalblue", 0x4169e1),
    ("saddlebrown", 0x8b4513),
    ("salmon", 0xfa8072),
    ("sandybrown", 0xf4a460),
    ("seagreen", 0x2e8b57),
    ("seashell", 0xfff5ee),
    ("sienna", 0xa0522d),
    ("silver", 0xc0c0c0),
    ("skyblue", 0x87ceeb),
    ("slateblue", 0x6a5acd),
    ("slategray", 0x708090),
    ("snow", 0xfffafa),
    ("springgreen", 0x00ff7f),
    ("steelblue", 0x4682b4),
    ("tan", 0xd2b48c),
    ("teal", 0x008080),
    ("thistle", 0xd8bfd8),
    ("tomato", 0xff6347),
    ("turquoise", 0x40e0d0),
    ("violet", 0xee82ee),
    ("violetred", 0xd02090),
    ("wheat", 0xf5deb3),
    ("white", 0xffffff),
    ("whitesmoke", 0xf5f5f5),
    ("yellow", 0xffff00),
    ("yellowgreen", 0x9acd32),
];

/// The colour X3DOM reads for a colour name, as 0xRRGGBB.
pub fn color_name(name: &str) -> Option<u32> {
    COLOR_NAMES
        .binary_search_by(|(known, _)| known.cmp(&name))
        .ok()
        .map(|i| COLOR_NAMES[i].1)
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
        assert!(COLOR_NAMES.windows(2).all(|w| w[0].0 < w[1].0));
        assert_eq!(color_name("feldspar"), Some(0xd19275));
        assert_eq!(color_name("lightgray"), None);
        assert_eq!(color_name("Red"), None);
    }
}
