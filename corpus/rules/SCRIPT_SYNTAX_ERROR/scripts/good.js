function initialize() {
  print('loaded');
}
