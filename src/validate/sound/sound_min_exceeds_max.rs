//! SOUND_MIN_EXCEEDS_MAX: a Sound whose inner ellipsoid reaches past its outer one
//! (minFront above maxFront, or minBack above maxBack).

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Sound node whose effective `minFront` (default 1) is greater than its
    /// effective `maxFront` (default 10), or whose `minBack` (default 1) is greater than
    /// its `maxBack` (default 10), compared as the f32 values the fields hold. Fields a
    /// ROUTE sends values to or that take their value through `IS` are left alone, as are
    /// NaN and infinities (FIELD_VALUE_NONFINITE's).
    ///
    /// ## Why it matters
    /// The `min` distances bound the inner ellipsoid, where the sound plays at full
    /// loudness, and the `max` distances the outer one, beyond which nothing is heard;
    /// between them the loudness falls by 20 dB. An inner ellipsoid that reaches past the
    /// outer one leaves no ramp to fall along: what the listener hears between the two
    /// boundaries depends on the browser. Often the values were swapped, or only `max`
    /// was lowered and `min` kept its default.
    ///
    /// ## Example
    /// ```xml
    /// <Sound minFront='20' maxFront='10'>
    ///   <AudioClip url='"chime.wav"'/>
    /// </Sound>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Sound minFront='10' maxFront='20'>
    ///   <AudioClip url='"chime.wav"'/>
    /// </Sound>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 16.4.2 Sound (X3D 3.x; ISO/IEC 14772-1 6.42 Sound for VRML97, in the same
    /// words): "The minFront, maxFront, minBack, and maxBack fields are defined in local
    /// coordinates, and shall be greater than or equal to zero. The minBack field shall be
    /// less than or equal to maxBack, and minFront shall be less than or equal to
    /// maxFront." The first sentence is the fields' range, which FIELD_OUT_OF_RANGE checks.
    /// > "The minBack field shall be less than or equal to maxBack, and minFront shall be less than or equal to maxFront" (19775-1 16.4.2)
    pub static SOUND_MIN_EXCEEDS_MAX = {
        severity: Error,
        level: Standard,
        clause: "16.4.2",
        versions: "all",
        check: Some(check),
    }
}

/// The (inner, outer) distance pairs along the direction vector.
const PAIRS: [(&str, &str); 2] = [("minFront", "maxFront"), ("minBack", "maxBack")];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Sound") {
        let node = doc.node(id);
        for (min_field, max_field) in PAIRS {
            if set_elsewhere(doc, &routed, id, min_field)
                || set_elsewhere(doc, &routed, id, max_field)
            {
                continue;
            }
            let (Some(min), Some(max)) = (doc.f32_of(id, min_field), doc.f32_of(id, max_field))
            else {
                continue;
            };
            // A non-finite value is FIELD_VALUE_NONFINITE's: it has no order to judge.
            if !(min > max && min.is_finite() && max.is_finite()) {
                continue;
            }
            let (min_entry, max_entry) = (node.entry(min_field), node.entry(max_field));
            let span = min_entry.or(max_entry).map_or(node.name_span, |e| e.span);
            let related = max_entry.filter(|_| min_entry.is_some()).map(|e| e.span);
            let message = format!(
                "Sound.{min_field} {} is greater than {max_field} {}{}",
                readable(min.into()),
                readable(max.into()),
                if max_entry.is_none() {
                    " (its default)"
                } else {
                    ""
                }
            );
            found.push((id, span, related, message, max_field));
        }
    }
    for (id, span, related, message, max_field) in found {
        let mut diagnostic = Diagnostic::new(&SOUND_MIN_EXCEEDS_MAX, span, message)
            .node(id)
            .help("the inner ellipsoid (min) shall lie within the outer one (max): swap the values or raise the max");
        if let Some(related) = related {
            diagnostic = diagnostic.related(related, max_field);
        }
        ctx.report(diagnostic);
    }
}
