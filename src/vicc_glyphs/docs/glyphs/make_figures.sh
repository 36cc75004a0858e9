#!/bin/sh
# Regenerates the design figures in this directory. Usage: make_figures.sh PATH/TO/vicc_glyph
set -e
tool=${1:?usage: make_figures.sh PATH/TO/vicc_glyph}
here=$(cd "$(dirname "$0")" && pwd)
designs="$here/../../designs"
for p in 95 85 75 65 40; do
  "$tool" design "$designs/rain_forecast_sine.yaml" --values probability=$p,amount=5 \
    --out "$here/rain_forecast_sine_probability$p.png" --size 160
done
for a in 1 5 20; do
  "$tool" design "$designs/rain_forecast_sine.yaml" --values probability=95,amount=$a \
    --out "$here/rain_forecast_sine_amount$a.png" --size 160
  "$tool" design "$designs/rain_forecast_dashes.yaml" --values probability=50,amount=$a \
    --out "$here/rain_forecast_dashes_amount$a.png" --size 160
done
for p in 95 85 75 65 40; do
  "$tool" design "$designs/rain_forecast_dashes.yaml" --values probability=$p,amount=20 \
    --out "$here/rain_forecast_dashes_probability$p.png" --size 160
done
for v in 10,category=0 18,category=1 27,category=2 45,category=2; do
  "$tool" design "$designs/intracranial_pressure.yaml" --values pressure=$v \
    --out "$here/intracranial_pressure_${v%%,*}.png" --size 160
done
covid() {
  "$tool" design "$designs/covid19_gradient.yaml" --out "$here/covid19_gradient_$1.png" \
    --size 160 --values "$2"
}
covid steady_low incidence=30,hospitalisation=0.5,incidence_change=0,hospitalisation_change=0
covid rising incidence=400,hospitalisation=3.5,incidence_change=15,hospitalisation_change=30
covid falling incidence=150,hospitalisation=2,incidence_change=-15,hospitalisation_change=-30
covid steady_high incidence=1500,hospitalisation=6,incidence_change=0,hospitalisation_change=0
"$tool" design-map "$designs/covid19_gradient.yaml" \
  --table "$designs/data/covid19_german_states_illustrative.csv" \
  --out "$here/covid19_gradient_map_german_states_illustrative.png" --glyph-size 96 --width 820
# The README's overview: seven of the figures above side by side (needs ImageMagick).
if command -v convert >/dev/null 2>&1; then
  (cd "$here" && convert rain_forecast_sine_probability40.png rain_forecast_sine_amount5.png \
    rain_forecast_dashes_probability85.png covid19_gradient_falling.png \
    covid19_gradient_steady_low.png intracranial_pressure_10.png intracranial_pressure_45.png \
    -bordercolor white -border 4 +append overview.png)
else
  echo "make_figures.sh: no ImageMagick 'convert': overview.png not updated" >&2
fi
