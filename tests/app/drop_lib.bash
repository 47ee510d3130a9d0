# Shared by the resume tests (after script_lib.bash): the 40 ms drop (drop.yaml) with a flow
# probe, written to $tmp/drop.yaml, and the outputs a resumed run must give byte for byte.
sed -e "s|\.\./\.\./shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/drop.yaml"
cat >> "$tmp/drop.yaml" << 'YAML'
  probes:
    - flow: {name: through, point: [0, 0, 0.05], normal: [0, 0, -1]}
YAML
drop_outputs=(energy.csv driver_floor.csv driver_left.csv driver_right.csv through.csv scene.pvd)
