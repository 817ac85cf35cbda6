//! Every language has every message of English's, no other, with the same
//! placeables; every id the code asks for is in English's file.

use std::collections::{BTreeMap, BTreeSet};

use fluent_syntax::ast;

use super::*;

/// A message's parts (`id` and `id.attribute`), each with its placeables.
type Parts = BTreeMap<String, BTreeSet<String>>;

fn parts(language: Language) -> Parts {
    let resource = fluent_syntax::parser::parse(source(language))
        .unwrap_or_else(|(_, errors)| panic!("{language}: {errors:?}"));
    let mut parts = Parts::new();
    for entry in resource.body {
        if let ast::Entry::Message(message) = entry {
            let id = message.id.name;
            if let Some(value) = &message.value {
                parts.insert(id.to_owned(), placeables(value));
            }
            for attribute in &message.attributes {
                parts.insert(
                    format!("{id}.{}", attribute.id.name),
                    placeables(&attribute.value),
                );
            }
        }
    }
    parts
}

fn placeables(pattern: &ast::Pattern<&str>) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for element in &pattern.elements {
        if let ast::PatternElement::Placeable { expression } = element {
            expression_placeables(expression, &mut names);
        }
    }
    names
}

fn expression_placeables(expression: &ast::Expression<&str>, names: &mut BTreeSet<String>) {
    let inline = |inline: &ast::InlineExpression<&str>, names: &mut BTreeSet<String>| {
        if let ast::InlineExpression::VariableReference { id } = inline {
            names.insert(id.name.to_owned());
        }
    };
    match expression {
        ast::Expression::Inline(e) => inline(e, names),
        ast::Expression::Select { selector, variants } => {
            inline(selector, names);
            for variant in variants {
                names.extend(placeables(&variant.value));
            }
        }
    }
}

#[test]
fn every_file_reads_without_a_problem() {
    for language in Language::CHOSEN_FROM.into_iter().chain([Language::Pseudo]) {
        assert_eq!(words(language).problems(), &[] as &[String], "{language}");
        assert_eq!(words(language).language(), language);
    }
}

#[test]
fn every_language_has_english_s_messages_and_placeables_and_no_others() {
    let english = parts(Language::English);
    assert!(english.len() > 20, "English has {} messages", english.len());
    for language in &Language::CHOSEN_FROM[1..] {
        let translated = parts(*language);
        let missing: Vec<_> = english
            .keys()
            .filter(|id| !translated.contains_key(*id))
            .collect();
        let extra: Vec<_> = translated
            .keys()
            .filter(|id| !english.contains_key(*id))
            .collect();
        assert!(missing.is_empty(), "{language} lacks {missing:?}");
        assert!(
            extra.is_empty(),
            "{language} has ids English has not: {extra:?}"
        );
        for (id, names) in &english {
            assert_eq!(&translated[id], names, "{language}: {id}'s placeables");
        }
    }
}

#[test]
fn every_id_the_code_names_is_in_english_s_file() {
    let english = parts(Language::English);
    let mut named = 0;
    let mut stack = vec![std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/src"
    ))];
    while let Some(path) = stack.pop() {
        if path.is_dir() {
            stack.extend(std::fs::read_dir(&path).unwrap().map(|e| e.unwrap().path()));
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        // Every `tr!` whose id is a literal, in whatever spacing rustfmt
        // gave it (an id in a variable is checked where it is named).
        for (at, _) in text.match_indices("tr!(") {
            let rest = &text[at..];
            let Some(comma) = rest.find(',') else {
                continue;
            };
            let Some(rest) = rest[comma + 1..].trim_start().strip_prefix('"') else {
                continue;
            };
            let id = &rest[..rest.find('"').unwrap()];
            named += 1;
            assert!(
                english.contains_key(id),
                "{}: {id} is not in en.ftl",
                path.display()
            );
        }
    }
    assert!(named > 20, "only {named} ids named");
}

#[test]
fn polish_counts_take_their_three_forms() {
    let polish = words(Language::Polish);
    let form = |n: i64| {
        let text = tr!(polish, "rods-count", count = n);
        assert!(text.contains(&n.to_string()), "{text}");
        text.replace(|c: char| c.is_ascii_digit(), "")
    };
    // one (1), few (2, 3, 4, 22), many (5, 12, 25): three forms.
    assert_eq!(form(1), " pręt");
    for n in [2, 3, 4, 22] {
        assert_eq!(form(n), " pręty", "{n}");
    }
    for n in [5, 12, 25] {
        assert_eq!(form(n), " prętów", "{n}");
    }
}

#[test]
fn a_missing_translation_falls_back_to_english_and_an_unknown_id_shows_itself() {
    assert_eq!(
        words(Language::German).get("no-such-message"),
        "no-such-message"
    );
    let pseudo = tr!(words(Language::Pseudo), "rods-count", count = 3);
    let english = tr!(words(Language::English), "rods-count", count = 3);
    assert!(
        pseudo.chars().count() > english.chars().count(),
        "{pseudo} / {english}"
    );
    assert!(
        pseudo.contains('3'),
        "placeables are not transformed: {pseudo}"
    );
}
