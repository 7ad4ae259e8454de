//! Mutated STEP files: each class of bad input the reader must refuse
//! cleanly (or read), made from a good file's text. Used by the bad-input
//! corpus tests of the library, the command line and the C ABI (std only,
//! so the C ABI's tests can include it by path).

/// A mutated file: its class, a name for messages and file names, its
/// bytes, and the error code (`read.<code>`) it must end with, if the class
/// decides one.
pub struct Mutant {
    pub class: &'static str,
    pub name: String,
    pub bytes: Vec<u8>,
    pub expect: Option<&'static str>,
}

/// Every mutation of `text` (a part named `base`): self-referencing units,
/// extreme reals, non-positive radii, extreme knots, truncations and
/// garbage. The assembly classes need an assembly: [`assembly_corpus`].
pub fn corpus(base: &str, text: &str) -> Vec<Mutant> {
    let mut out = Vec::new();
    let mut push = |class: &'static str, what: String, t: Option<String>, expect| {
        if let Some(t) = t {
            out.push(Mutant {
                class,
                name: format!("{base}.{class}.{what}"),
                bytes: t.into_bytes(),
                expect,
            });
        }
    };
    for angle in [false, true] {
        let what = if angle { "angle" } else { "length" };
        push(
            "unit_self",
            what.into(),
            unit_cycle(text, angle, false),
            Some("cyclic_reference"),
        );
        push(
            "unit_pair",
            what.into(),
            unit_cycle(text, angle, true),
            Some("cyclic_reference"),
        );
    }
    for v in ["1.E300", "1.E-320"] {
        push(
            "unit_factor",
            v.into(),
            unit_factor(text, v),
            Some("bad_number"),
        );
    }
    for v in ["1.E308", "-1.E308", "1.E12"] {
        push(
            "vertex_coordinate",
            v.into(),
            vertex_coordinate(text, v),
            Some("bad_number"),
        );
    }
    for (keyword, vs) in [
        ("CIRCLE", &["-1.E308", "0.", "1.E308"][..]),
        ("CYLINDRICAL_SURFACE", &["-5.", "0.", "1.E308"][..]),
    ] {
        for v in vs {
            push(
                "radius",
                format!("{keyword}.{v}"),
                last_number_of(text, keyword, v),
                Some("bad_number"),
            );
        }
    }
    for v in ["1.E308", "1.E-320", "-1.E308"] {
        push("knot", v.into(), first_knot(text, v), None);
    }
    for k in 1..=4 {
        let cut = text.len() * k / 5;
        let cut = (0..=cut)
            .rev()
            .find(|i| text.is_char_boundary(*i))
            .unwrap_or(0);
        push(
            "truncated",
            format!("{k}of5"),
            Some(text[..cut].to_string()),
            None,
        );
    }
    out.push(Mutant {
        class: "garbage",
        name: format!("{base}.garbage.zeros"),
        bytes: vec![0u8; 1 << 16],
        expect: Some("syntax"),
    });
    out
}

/// Mutations that need an assembly (`text` places one part twice at the
/// top, as `fixtures/bracket_assembly.step` does: root definition #5 with
/// representation #10, the part #31 with representation #36, placements
/// #11, #15, #19): a cycle with no outside root, a binary tree of
/// `2^depth` instances, and `mapped` mapped items at distinct places.
pub fn assembly_corpus(base: &str, text: &str, depth: u32, mapped: usize) -> Vec<Mutant> {
    let mutant = |class, what: &str, t: String, expect| Mutant {
        class,
        name: format!("{base}.{class}.{what}"),
        bytes: t.into_bytes(),
        expect: Some(expect),
    };
    let rootless = append(
        text,
        "#990001 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('c','cycle','',#31,#5,$);\n",
    );
    vec![
        mutant("rootless_cycle", "two", rootless, "cyclic_assembly"),
        mutant(
            "amplifying_tree",
            &depth.to_string(),
            binary_tree(text, depth),
            "budget_exceeded",
        ),
        mutant(
            "mapped_items",
            &mapped.to_string(),
            mapped_items(text, mapped),
            "budget_exceeded",
        ),
    ]
}

/// `text` with `extra` statements before the data section's end.
fn append(text: &str, extra: &str) -> String {
    let end = text.rfind("ENDSEC;").expect("a data section");
    format!("{}{extra}{}", &text[..end], &text[end..])
}

/// The byte range of statement `#id = …;`.
fn statement(text: &str, id: u64) -> Option<std::ops::Range<usize>> {
    for pat in [format!("#{id} ="), format!("#{id}=")] {
        let mut from = 0;
        while let Some(at) = text[from..].find(&pat).map(|i| i + from) {
            let at_start =
                text[..at].trim_end().ends_with(';') || text[..at].trim_end().ends_with("DATA");
            if at_start {
                let end = text[at..].find(';')? + at + 1;
                return Some(at..end);
            }
            from = at + pat.len();
        }
    }
    None
}

/// The statements in file order: (id, range).
fn statements(text: &str) -> Vec<(u64, std::ops::Range<usize>)> {
    let data = text.find("DATA;").map_or(0, |d| d + 5);
    let mut out = Vec::new();
    let mut at = data;
    while let Some(h) = text[at..].find('#').map(|i| i + at) {
        let digits: String = text[h + 1..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        let rest = text[h + 1 + digits.len()..].trim_start();
        match (digits.parse::<u64>(), rest.starts_with('=')) {
            (Ok(id), true) => {
                let Some(end) = text[h..].find(';').map(|i| i + h + 1) else {
                    break;
                };
                out.push((id, h..end));
                at = end;
            }
            _ => at = h + 1,
        }
    }
    out
}

/// The first statement whose text has every one of `words`.
fn find(text: &str, words: &[&str]) -> Option<(u64, std::ops::Range<usize>)> {
    statements(text)
        .into_iter()
        .find(|(_, r)| words.iter().all(|w| text[r.clone()].contains(w)))
}

/// The first statement with every one of `words` among the entities the
/// first closed shell reaches (so the solid is built from it: geometry of
/// annotations or of a surface model beside the solid is not).
fn find_in_solid(text: &str, words: &[&str]) -> Option<(u64, std::ops::Range<usize>)> {
    let all = statements(text);
    let by_id: std::collections::HashMap<u64, std::ops::Range<usize>> =
        all.iter().cloned().collect();
    let (shell, _) = find(text, &["CLOSED_SHELL"])?;
    let mut reached = std::collections::HashSet::from([shell]);
    let mut todo = vec![shell];
    while let Some(id) = todo.pop() {
        let Some(r) = by_id.get(&id) else { continue };
        let body = &text[r.clone()];
        let body = &body[body.find('=').unwrap_or(0)..];
        for part in body.split('#').skip(1) {
            let digits: String = part.chars().take_while(char::is_ascii_digit).collect();
            if let Ok(next) = digits.parse::<u64>() {
                if reached.insert(next) {
                    todo.push(next);
                }
            }
        }
    }
    all.into_iter()
        .find(|(id, r)| reached.contains(id) && words.iter().all(|w| text[r.clone()].contains(w)))
}

fn largest_id(text: &str) -> u64 {
    statements(text)
        .iter()
        .map(|(id, _)| *id)
        .max()
        .unwrap_or(0)
}

fn replace(text: &str, r: std::ops::Range<usize>, with: &str) -> String {
    format!("{}{with}{}", &text[..r.start], &text[r.end..])
}

/// The length (or angle) unit made a conversion-based unit measured in
/// itself (or in a second one measured in the first).
fn unit_cycle(text: &str, angle: bool, pair: bool) -> Option<String> {
    let (kind, measure) = if angle {
        ("PLANE_ANGLE_UNIT", "PLANE_ANGLE_MEASURE")
    } else {
        ("LENGTH_UNIT", "LENGTH_MEASURE")
    };
    let (u, r) = find(text, &[kind, "SI_UNIT"])?;
    let n = largest_id(text) + 1;
    let (m1, d, v, m2) = (n, n + 1, n + 2, n + 3);
    let target = if pair { v } else { u };
    let mut extra = format!(
        "#{m1} = {measure}_WITH_UNIT({measure}(1.),#{target});\n\
         #{d} = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"
    );
    if pair {
        extra.push_str(&format!(
            "#{v} = ( CONVERSION_BASED_UNIT('B',#{m2}) {kind}() NAMED_UNIT(#{d}) );\n\
             #{m2} = {measure}_WITH_UNIT({measure}(1.),#{u});\n"
        ));
    }
    let unit = format!("#{u} = ( CONVERSION_BASED_UNIT('A',#{m1}) {kind}() NAMED_UNIT(#{d}) );");
    Some(append(&replace(text, r, &unit), &extra))
}

/// The length unit a conversion of `factor` metres.
fn unit_factor(text: &str, factor: &str) -> Option<String> {
    let (u, r) = find(text, &["LENGTH_UNIT", "SI_UNIT"])?;
    let n = largest_id(text) + 1;
    let (m, d, si) = (n, n + 1, n + 2);
    let unit =
        format!("#{u} = ( CONVERSION_BASED_UNIT('X',#{m}) LENGTH_UNIT() NAMED_UNIT(#{d}) );");
    let extra = format!(
        "#{m} = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE({factor}),#{si});\n\
         #{d} = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n\
         #{si} = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.) );\n"
    );
    Some(append(&replace(text, r, &unit), &extra))
}

/// The point of the first vertex at (`v`, 0, 0).
fn vertex_coordinate(text: &str, v: &str) -> Option<String> {
    let (_, r) = find_in_solid(text, &["VERTEX_POINT"])?;
    let s = &text[r];
    let p: u64 = s[s.rfind('#')? + 1..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect::<String>()
        .parse()
        .ok()?;
    let pr = statement(text, p)?;
    Some(replace(
        text,
        pr,
        &format!("#{p} = CARTESIAN_POINT('',({v},0.,0.));"),
    ))
}

/// The last number of the first `keyword` statement (a radius) set to `v`.
fn last_number_of(text: &str, keyword: &str, v: &str) -> Option<String> {
    let (_, r) = find_in_solid(text, &[&format!("{keyword}(")])?;
    let s = &text[r.clone()];
    let close = s.rfind(')')?;
    let comma = s[..close].rfind(',')?;
    let new = format!("{}{v}{}", &s[..comma + 1], &s[close..]);
    Some(replace(text, r, &new))
}

/// The first knot of the first B-spline curve set to `v`.
fn first_knot(text: &str, v: &str) -> Option<String> {
    let (_, r) = find_in_solid(text, &["B_SPLINE_CURVE_WITH_KNOTS"])?;
    let s = &text[r.clone()];
    // The knots: the last parenthesised list of reals in the statement.
    let mut best = None;
    for (open, _) in s.match_indices('(') {
        let Some(len) = s[open + 1..].find(')') else {
            continue;
        };
        let inner = &s[open + 1..open + 1 + len];
        let numeric = !inner.is_empty()
            && inner.contains('.')
            && inner
                .chars()
                .all(|c| c.is_ascii_digit() || ".,Ee+- \n\r".contains(c));
        if numeric {
            best = Some((open + 1, inner.find(',').unwrap_or(inner.len())));
        }
    }
    let (start, len) = best?;
    let new = format!("{}{v}{}", &s[..start], &s[start + len..]);
    Some(replace(text, r, &new))
}

/// A definition that uses the one below it twice, `depth` levels over the
/// part: `2^depth` instances of it, at as many places (one of the two
/// placements turns, so their compositions do not repeat).
fn binary_tree(text: &str, depth: u32) -> String {
    let mut next = largest_id(text) + 1;
    let mut id = || {
        next += 1;
        next
    };
    let (turned, moved) = (id(), id());
    let (p1, p2, d1) = (id(), id(), id());
    let mut extra = format!(
        "#{turned} = AXIS2_PLACEMENT_3D('',#{p1},#13,#{d1});\n\
         #{moved} = AXIS2_PLACEMENT_3D('',#{p2},#13,#14);\n\
         #{p1} = CARTESIAN_POINT('',(150.,0.,0.));\n\
         #{p2} = CARTESIAN_POINT('',(0.,170.,0.));\n\
         #{d1} = DIRECTION('',(0.6,0.8,0.));\n"
    );
    let (mut child_pd, mut child_rep) = (31u64, 36u64);
    for _ in 0..depth {
        let (pd, pds, sdr, rep) = (id(), id(), id(), id());
        extra.push_str(&format!(
            "#{pd} = PRODUCT_DEFINITION('design','',#32,#35);\n\
             #{pds} = PRODUCT_DEFINITION_SHAPE('','',#{pd});\n\
             #{sdr} = SHAPE_DEFINITION_REPRESENTATION(#{pds},#{rep});\n\
             #{rep} = SHAPE_REPRESENTATION('',(#11,#15,#19),#23);\n"
        ));
        for placement in [turned, moved] {
            let (cdsr, rr, idt, ps, nauo) = (id(), id(), id(), id(), id());
            extra.push_str(&format!(
                "#{cdsr} = CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#{rr},#{ps});\n\
                 #{rr} = ( REPRESENTATION_RELATIONSHIP('','',#{child_rep},#{rep}) \
                 REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#{idt}) SHAPE_REPRESENTATION_RELATIONSHIP() );\n\
                 #{idt} = ITEM_DEFINED_TRANSFORMATION('','',#11,#{placement});\n\
                 #{ps} = PRODUCT_DEFINITION_SHAPE('Placement','',#{nauo});\n\
                 #{nauo} = NEXT_ASSEMBLY_USAGE_OCCURRENCE('{nauo}','','',#{pd},#{child_pd},$);\n"
            ));
        }
        (child_pd, child_rep) = (pd, rep);
    }
    append(text, &extra)
}

/// `n` mapped items of the part's representation, each at its own place.
fn mapped_items(text: &str, n: usize) -> String {
    let mut next = largest_id(text) + 1;
    let map = next;
    let mut extra = format!("#{map} = REPRESENTATION_MAP(#11,#36);\n");
    let mut items = Vec::with_capacity(n);
    for k in 0..n {
        let (item, place, point) = (next + 1, next + 2, next + 3);
        next += 3;
        extra.push_str(&format!(
            "#{item} = MAPPED_ITEM('',#{map},#{place});\n\
             #{place} = AXIS2_PLACEMENT_3D('',#{point},#13,#14);\n\
             #{point} = CARTESIAN_POINT('',({}.,0.,0.));\n",
            (k as u64) * 200
        ));
        items.push(format!("#{item}"));
    }
    let rep = next + 1;
    extra.push_str(&format!(
        "#{rep} = SHAPE_REPRESENTATION('',({}),#23);\n",
        items.join(",")
    ));
    append(text, &extra)
}

/// One mutant of each class — of `part` (a single part's text) and of
/// `assembly` (see [`assembly_corpus`]) — written to `dir` as
/// `<name>.step`: each file's path, class and expected code.
pub fn one_of_each_class(
    dir: &std::path::Path,
    base: &str,
    part: &str,
    assembly: &str,
) -> Vec<(std::path::PathBuf, &'static str, Option<&'static str>)> {
    let mut all = corpus(base, part);
    all.extend(assembly_corpus("bracket_assembly", assembly, 15, 20_000));
    let mut seen = std::collections::HashSet::new();
    all.into_iter()
        .filter(|m| seen.insert(m.class))
        .map(|m| {
            let path = dir.join(format!("{}.step", m.name));
            std::fs::write(&path, &m.bytes).expect("a writable directory");
            (path, m.class, m.expect)
        })
        .collect()
}
