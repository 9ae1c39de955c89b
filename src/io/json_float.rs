//! A floating-point field of a JSON header that may be NaN or ±∞ (JSON has no such numbers): written as a
//! number when finite, else as the string `NaN`, `inf` or `-inf`, and read back either way, so that a
//! checkpoint restores it bit for bit. Use with `#[serde(with = "crate::io::json_float")]`.

use serde::{Deserialize, Deserializer, Serializer};

pub fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
    if x.is_finite() {
        s.serialize_f64(*x)
    } else if x.is_nan() {
        s.serialize_str("NaN")
    } else if *x > 0.0 {
        s.serialize_str("inf")
    } else {
        s.serialize_str("-inf")
    }
}

pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Either {
        Number(f64),
        Text(String),
    }
    match Either::deserialize(d)? {
        Either::Number(x) => Ok(x),
        Either::Text(t) => match t.as_str() {
            "NaN" => Ok(f64::NAN),
            "inf" => Ok(f64::INFINITY),
            "-inf" => Ok(f64::NEG_INFINITY),
            other => Err(serde::de::Error::custom(format!(
                "`{other}`: expected a number, `NaN`, `inf` or `-inf`"
            ))),
        },
    }
}

#[cfg(test)]
mod tests {
    #[derive(serde::Serialize, serde::Deserialize)]
    struct S {
        #[serde(with = "super")]
        x: f64,
    }

    #[test]
    fn every_float_comes_back_bit_for_bit() {
        for x in [0.1 + 0.2, -1e-300, f64::MAX, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let back: S = serde_json::from_str(&serde_json::to_string(&S { x }).unwrap()).unwrap();
            assert!(
                back.x.to_bits() == x.to_bits() || (x.is_nan() && back.x.is_nan()),
                "{x}"
            );
        }
        assert!(serde_json::from_str::<S>(r#"{"x":"much"}"#).is_err());
    }
}
