//! PICKING_GEOMETRY_TYPE_INVALID: a pick sensor whose pickingGeometry is a geometry its
//! type does not pick with.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LinePickSensor whose `pickingGeometry` is not an IndexedLineSet or
    /// LineSet, a PointPickSensor whose `pickingGeometry` is not a PointSet, and a
    /// PrimitivePickSensor whose `pickingGeometry` is not a Box, Cone, Cylinder or
    /// Sphere. Only geometry nodes are judged: a node that is no geometry at all is
    /// NODE_TYPE_NOT_ALLOWED's, and a prototype instance is left alone (its type is that
    /// of its first body node, not checked here). VolumePickSensor takes any geometry.
    ///
    /// ## Why it matters
    /// Each sensor defines its picking from one kind of geometry: line segments, points,
    /// or a primitive's exact shape. With another geometry the sensor has nothing it knows
    /// how to intersect, and browsers pick nothing or fall back to bounding boxes.
    ///
    /// ## Example
    /// ```xml
    /// <PrimitivePickSensor>
    ///   <IndexedFaceSet containerField='pickingGeometry' coordIndex='0 1 2'>
    ///     <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    ///   </IndexedFaceSet>
    /// </PrimitivePickSensor>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <PrimitivePickSensor>
    ///   <Sphere containerField='pickingGeometry' radius='0.5'/>
    /// </PrimitivePickSensor>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 38.3.2 X3DPickSensorNode leaves the allowed node types to the concrete
    /// nodes, whose interface tables in 38.4 give them: `pickingGeometry NULL
    /// [IndexedLineSet|LineSet]` (LinePickSensor), `[PointSet]` (PointPickSensor),
    /// `[Cone|Cylinder|Sphere|Box]` (PrimitivePickSensor). 38.3.2's own sentence was not
    /// found in any copy of the text (issue 33); the error rests on the grammar: the X3D
    /// XML schema's content model of each sensor admits only these geometry elements as
    /// its `pickingGeometry` (any other geometry there does not validate):
    /// > "<xs:element ref="Box"/> <xs:element ref="Cone"/> <xs:element ref="Cylinder"/> <xs:element ref="Sphere"/>" (x3d-4.0.xsd, PrimitivePickSensor, the `pickingGeometry` choice; LineSet and IndexedLineSet for LinePickSensor, PointSet for PointPickSensor)
    pub static PICKING_GEOMETRY_TYPE_INVALID = {
        severity: Error,
        level: Standard,
        clause: "38.4",
        versions: "all",
        check: Some(check),
    }
}

/// The pick sensors with a closed list of picking geometries, and that list.
const ALLOWED: [(&str, &[&str]); 3] = [
    ("LinePickSensor", &["IndexedLineSet", "LineSet"]),
    ("PointPickSensor", &["PointSet"]),
    (
        "PrimitivePickSensor",
        &["Box", "Cone", "Cylinder", "Sphere"],
    ),
];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (sensor, allowed) in ALLOWED {
        for id in doc.nodes_of_type(sensor) {
            let Some(geometry) = doc.child_of(id, "pickingGeometry") else {
                continue;
            };
            let geometry_node = doc.node(geometry);
            if !geometry_node.is_a("X3DGeometryNode")
                || allowed.contains(&geometry_node.type_name())
            {
                continue;
            }
            found.push((
                id,
                geometry_node.name_span,
                sensor,
                geometry_node.type_name().to_string(),
                allowed,
            ));
        }
    }
    for (id, span, sensor, geometry, allowed) in found {
        ctx.report(
            Diagnostic::new(
                &PICKING_GEOMETRY_TYPE_INVALID,
                span,
                format!(
                    "{sensor}.pickingGeometry is {geometry}, but a {sensor} picks only with {}",
                    either(allowed)
                ),
            )
            .node(id)
            .help(format!("use {} as the pickingGeometry", either(allowed))),
        );
    }
}

/// "A", "A or B", "A, B, C or D".
fn either(types: &[&str]) -> String {
    match types.split_last() {
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}
