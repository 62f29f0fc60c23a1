//! What an output records of a run's settings: the CSV header's lines and
//! the JSON `params` entries, in the table's order and presence rules.

use serde::ser::SerializeMap;

use super::{Param, Presence, Settings, Value, PARAMS};

impl Settings {
    /// Whether any loss setting differs from its default.
    fn losses_differ(&self) -> bool {
        self.options.losses != crate::Losses::default()
    }

    fn present(&self, presence: Presence, value: &Value) -> bool {
        match presence {
            Presence::Always => true,
            Presence::WhenSet => *value != Value::None,
            Presence::WithLosses => self.losses_differ(),
        }
    }

    /// The `key = value` lines of a CSV output's header, in section order,
    /// then table order: numbers in their shortest exact form, so that the
    /// header read back reproduces the run bit for bit.
    pub fn csv_lines(&self) -> Vec<(&'static str, String)> {
        let mut params: Vec<&Param> = PARAMS.iter().collect();
        params.sort_by_key(|p| p.csv.0); // stable: table order within a section
        params
            .into_iter()
            .filter_map(|p| {
                let v = p.get(self);
                self.present(p.csv.1, &v).then(|| (p.key, p.text(&v)))
            })
            .collect()
    }

    /// The parameters of a JSON output's `params`, in table order, as
    /// [`Settings::serialize_record`] writes them.
    pub fn json_entries(&self) -> Vec<(&'static str, Value)> {
        PARAMS
            .iter()
            .filter_map(|p| {
                let v = p.get(self);
                self.present(p.json, &v).then_some((p.key, v))
            })
            .collect()
    }

    /// Writes [`Settings::json_entries`] into the map `map`.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize_record<M: SerializeMap>(&self, map: &mut M) -> Result<(), M::Error> {
        for (k, v) in self.json_entries() {
            map.serialize_entry(k, &v)?;
        }
        Ok(())
    }
}
