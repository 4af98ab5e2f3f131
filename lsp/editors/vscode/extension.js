// The whole VS Code side of safegi-lsp: start the server on stdio for GLSL
// files and pass the settings as initializationOptions (docs/editor.md).
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const settings = vscode.workspace.getConfiguration('safegi');
  const serverOptions = { command: settings.get('serverPath'), transport: TransportKind.stdio };
  const clientOptions = {
    documentSelector: [{ scheme: 'file', language: 'glsl' }, { scheme: 'untitled', language: 'glsl' }],
    initializationOptions: {
      includePaths: settings.get('includePaths'),
      defines: settings.get('defines'),
      strict: settings.get('strict'),
    },
  };
  client = new LanguageClient('safegi', 'SafeGI', serverOptions, clientOptions);
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
