function set_fraction(value, time) {
  print(value);
}
